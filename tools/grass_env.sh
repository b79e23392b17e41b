# Sourced by the tools: runs GRASS commands in a throw-away XY location with
# the addon from ./dist on the PATH (nothing is installed anywhere).
#   sbrt_location DIR   creates DIR/loc (if needed)
#   in_grass MAPSET CMD...  runs CMD in DIR/loc/MAPSET (created if needed)
SBRT_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export GRASS_ADDON_BASE=$SBRT_ROOT/dist
export GRASS_SKIP_MAPSET_OWNER_CHECK=1
# docs/BUILD-NOTES.md 7: use the system python, whatever pyenv puts first
export PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin
sbrt_location() {
    SBRT_GISDBASE=$1
    mkdir -p "$SBRT_GISDBASE"
    [ -d "$SBRT_GISDBASE/loc/PERMANENT" ] || grass -c XY "$SBRT_GISDBASE/loc" -e >/dev/null 2>&1
}
in_grass() {
    local mapset=$1; shift
    [ -d "$SBRT_GISDBASE/loc/$mapset" ] || grass -c "$SBRT_GISDBASE/loc/$mapset" -e >/dev/null 2>&1
    grass "$SBRT_GISDBASE/loc/$mapset" --exec "$@"
}
