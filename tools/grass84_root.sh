#!/usr/bin/env bash
############################################################################
# MODULE:    tools/grass84_root.sh (r3.sbrt addon)
# PURPOSE:   The GRASS 8.4 leg of CI: a Debian 13 (trixie) root, made with
#            debootstrap from the archive apt already uses, with GRASS 8.4
#            and the packages of tools/setup.sh; the addon built there with
#            plain `make` and its gunittest files run there.
#              tools/grass84_root.sh prepare   makes the root (once: a second
#                  call returns at once; concurrent calls wait for the first)
#              tools/grass84_root.sh test      prepare, then a fresh copy of
#                  the working tree built and tested in the root; ends with
#                  the line "N passed, N failed", non-zero on any failure
#              tools/grass84_root.sh run CMD...  CMD in the root, in the
#                  last test's copy (to look into a failure there)
#            The root lives outside the checkout, in $SBRT_GRASS84_ROOT
#            (default /var/tmp/r3sbrt-debian13); the archives are
#            $SBRT_DEBIAN_MIRROR and $SBRT_DEBIAN_SECURITY (default: those
#            of the host's apt sources). Runs as root (debootstrap, mount,
#            chroot). On 2 busy cores: prepare 7 min, test 21 min (build 10,
#            gunittest files 10).
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
SBRT_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
root=${SBRT_GRASS84_ROOT:-/var/tmp/r3sbrt-debian13}
root=${root%/}
suite=trixie
marker=$root/.r3sbrt-prepared
lock=$root.lock
# the test's bound: a hung test must not hold CI
test_limit=${SBRT_GRASS84_TEST_SECONDS:-1800}

die() { echo "grass84_root: $*" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || die "run as root (debootstrap, mount and chroot need it)"
case "$root" in /|/usr*|/etc*|/var|/var/tmp|/tmp|"$SBRT_ROOT"*) die "SBRT_GRASS84_ROOT=$root: choose a folder of its own outside the checkout";; esac

# The Debian archives the host's apt uses (deb822 .sources or one-line
# .list), so that the root comes from the same place, e.g. a local mirror:
# host_archive debian|debian-security prints the first such URI, or nothing.
host_archive() {
    cat /etc/apt/sources.list /etc/apt/sources.list.d/*.sources /etc/apt/sources.list.d/*.list 2>/dev/null |
        grep -oE "(^URIs:|^deb)[[:space:]]+(\[[^]]*\][[:space:]]+)?[a-z]+://[^[:space:]]+/$1/?([[:space:]]|\$)" |
        grep -oE '[a-z]+://[^[:space:]]+' | head -1 || true # absent files, no match
}

# Mounts in the root, always undone (in reverse order) when the script ends.
mounted=()
mount_in() { # mount_in TARGET MOUNT-ARGS...
    local target=$root/$1; shift
    mount "$@" "$target"
    mounted+=("$target")
}
unmount_all() {
    local i
    for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
        umount -R "${mounted[i]}" 2>/dev/null || umount -R -l "${mounted[i]}" ||
            echo "grass84_root: could not unmount ${mounted[i]}" >&2
    done
    mounted=()
}
# Daemons a test left running in the root (Xvfb, munged, slurmd) would keep
# its mounts busy: end them, and only them (their root is this root).
end_root_processes() {
    local p pids=()
    for p in /proc/[0-9]*; do
        [ "$(readlink "$p/root" 2>/dev/null)" = "$root" ] && pids+=("${p#/proc/}")
    done
    [ ${#pids[@]} -eq 0 ] && return 0
    kill "${pids[@]}" 2>/dev/null || true
    sleep 1
    kill -9 "${pids[@]}" 2>/dev/null || true
}
finish() { end_root_processes; unmount_all; }
trap finish EXIT
trap 'exit 130' INT TERM

mount_all() {
    mount_in proc -t proc proc
    # /sys with its cgroup file systems (Slurm 24's slurmd will not start
    # without them) and /dev with /dev/pts and /dev/shm; rslave: no mount
    # made below them in the root reaches the host
    mount_in sys --rbind /sys
    mount --make-rslave "$root/sys"
    mount_in dev --rbind /dev
    mount --make-rslave "$root/dev"
    mount_in tmp -t tmpfs tmpfs
}
no_mounts_below() {
    ! grep -qF " $root/" /proc/mounts || die "something is still mounted below $root (see /proc/mounts)"
}
in_root() { # in_root CMD...: runs CMD in the root, a clean environment
    env -i HOME=/root TERM=dumb LANG=C.UTF-8 \
        PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
        chroot "$root" "$@"
}

# prepare, with the lock held
prepare_locked() {
    prepared && return 0
    local start=$SECONDS mirror security
    mirror=${SBRT_DEBIAN_MIRROR:-$(host_archive debian)}
    mirror=${mirror:-http://deb.debian.org/debian}
    security=${SBRT_DEBIAN_SECURITY:-$(host_archive debian-security)}
    if ! command -v debootstrap >/dev/null; then
        echo "grass84_root: installing debootstrap on the host"
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap >/dev/null ||
            { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap >/dev/null; }
    fi
    if [ ! -e "$root/.debootstrap-done" ]; then
        no_mounts_below
        rm -rf "$root" # a bootstrap that broke off
        echo "grass84_root: debootstrap $suite from $mirror into $root"
        debootstrap --variant=minbase "$suite" "$root" "$mirror" >"$root.debootstrap.log" 2>&1 ||
            { tail -20 "$root.debootstrap.log"; die "debootstrap failed (log $root.debootstrap.log)"; }
        touch "$root/.debootstrap-done"
    fi
    # the release and its updates, and the security fixes where the host
    # has them, from the host's archives
    rm -f "$root/etc/apt/sources.list"
    {
        printf 'Types: deb\nURIs: %s\nSuites: %s %s-updates\nComponents: main\n' "$mirror" "$suite" "$suite"
        printf 'Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg\n'
        [ -z "$security" ] ||
            printf '\nTypes: deb\nURIs: %s\nSuites: %s-security\nComponents: main\nSigned-By: %s\n' \
                "$security" "$suite" /usr/share/keyrings/debian-archive-keyring.gpg
    } >"$root/etc/apt/sources.list.d/debian.sources"
    cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
    # packages' scripts start no daemons in the root
    printf '#!/bin/sh\nexit 101\n' >"$root/usr/sbin/policy-rc.d"
    chmod 755 "$root/usr/sbin/policy-rc.d"
    # the project's own package list, the one Debian 12 uses
    cp "$SBRT_ROOT/tools/setup.sh" "$root/root/r3sbrt-setup.sh"
    mount_all
    echo "grass84_root: installing GRASS 8.4 and the build packages (tools/setup.sh)"
    in_root bash /root/r3sbrt-setup.sh
    in_root apt-get clean
    end_root_processes
    unmount_all
    echo "grass84_root: $(in_root grass --version 2>/dev/null | head -1) in $root"
    setup_digest >"$marker"
    echo "grass84_root: prepare took $((SECONDS - start)) s"
}

# The root is prepared when the marker names the tools/setup.sh it was
# made with (a package added later installs on the next prepare).
setup_digest() { sha256sum <"$SBRT_ROOT/tools/setup.sh" | cut -d' ' -f1; }
prepared() { [ -e "$marker" ] && [ "$(cat "$marker")" = "$(setup_digest)" ]; }

take_lock() {
    mkdir -p "$(dirname "$lock")"
    exec 9>"$lock"
    flock 9
}

prepare() {
    prepared && { echo "grass84_root: $root is ready"; return 0; }
    take_lock
    prepared && { echo "grass84_root: $root is ready"; return 0; }
    prepare_locked
}

# The working tree's files (tracked and untracked, not ignored: no dist/ or
# build outputs) copied into the root, built there with plain make and its
# gunittest files run there.
run_test() {
    take_lock
    prepare_locked
    local start=$SECONDS dest=/root/r3sbrt out rc
    no_mounts_below
    rm -rf "${root:?}$dest"
    mkdir -p "$root$dest"
    (cd "$SBRT_ROOT" && git ls-files -z --cached --others --exclude-standard |
        while IFS= read -r -d '' f; do
            [ -e "$f" ] || [ -L "$f" ] && printf '%s\0' "$f" # not a deleted tracked file
        done |
        tar --null -T - -cf -) | tar -C "$root$dest" -xf -
    # the host's name resolves as on the host (the Slurm test's one-node cluster)
    cp /etc/hosts "$root/etc/hosts"
    mount_all
    out=$root/tmp/grass84_test.log
    echo "grass84_root: building and testing in $root (GRASS $(in_root grass --config version))"
    set +e
    in_root timeout -k 10 "$test_limit" bash -c "cd $dest && {
            make -j\$(nproc) >/tmp/build.log 2>&1 || { tail -40 /tmp/build.log; echo 'build failed'; exit 1; }
            grep -E 'warning:' /tmp/build.log | sort -u | head -20
            echo \"built in \$SECONDS s\"
            tools/run_tests.sh gunittest
        }" 2>&1 | tee "$out"
    rc=${PIPESTATUS[0]}
    set -e
    [ "$rc" -eq 124 ] && echo "grass84_root: the test ran past ${test_limit} s"
    end_root_processes
    local summary
    summary=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$out" | tail -1)
    # the logs outlive the root's /tmp
    rm -rf "$root/root/r3sbrt-logs"
    mkdir -p "$root/root/r3sbrt-logs"
    cp -r "$root"/tmp/build.log "$root"/tmp/r3sbrt_tests.* "$out" "$root/root/r3sbrt-logs/" 2>/dev/null || true
    echo "grass84_root: logs in $root/root/r3sbrt-logs"
    unmount_all
    echo "grass84_root: test took $((SECONDS - start)) s"
    echo "${summary:-0 passed, 1 failed}"
    [ "$rc" -eq 0 ] && [ -n "$summary" ] && [ "${summary#* passed, }" = "0 failed" ]
}

# A command run in the root with its mounts, in the last test's copy
# (/root/r3sbrt): e.g. to look into a failure on GRASS 8.4.
run_in_root() {
    take_lock
    prepare_locked
    no_mounts_below
    mount_all
    set +e
    in_root bash -c 'cd /root/r3sbrt 2>/dev/null || cd /root; exec "$@"' bash "$@"
    local rc=$?
    set -e
    end_root_processes
    unmount_all
    return "$rc"
}

case "${1:-}" in
    prepare) prepare ;;
    test) run_test ;;
    run) shift; [ $# -gt 0 ] || die "usage: $0 run CMD..."; run_in_root "$@" ;;
    *) die "usage: $0 prepare|test|run CMD..." ;;
esac
