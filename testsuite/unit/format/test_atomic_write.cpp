/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   A write killed at any moment leaves the previous SBRT intact;
 *            staged copies, renames and removals of whole directories
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "format/atomic_dir.hpp"
#include "format/format.hpp"
#include "format/member_dir.hpp"
#include "test_support.hpp"
#include "util/error.hpp"
#include "builders/voxel_builder.hpp"

extern char **environ;

using namespace sbrt;

namespace {

Model model_with_seed(unsigned seed, int size)
{
    return sbrt_test::build_model(sbrt_test::random_voxels(seed, size, size, 40));
}

} // namespace

TEST(AtomicWrite, UncommittedWriteLeavesTargetUntouched)
{
    const std::string dir = sbrt_test::temp_dir("atomic") + "/m";
    const Model old_model = model_with_seed(1, 8);
    write_sbrt(dir, old_model, "old\n");
    {
        AtomicDirectory pending(dir);
        pending.write_file("stacks", std::string("garbage"));
        // destroyed without commit(): as if the conversion failed
    }
    const Model back = read_sbrt(dir);
    EXPECT_EQ(encode_stacks_v1(back), encode_stacks_v1(old_model));
    remove_tree(dir.substr(0, dir.rfind('/')));
}

TEST(AtomicWrite, CommitReplacesAWholeDirectory)
{
    const std::string dir = sbrt_test::temp_dir("atomic") + "/m";
    write_sbrt(dir, model_with_seed(1, 8), "old\n");
    const Model new_model = model_with_seed(2, 9);
    write_sbrt(dir, new_model, "new\n");
    EXPECT_EQ(encode_stacks_v1(read_sbrt(dir)), encode_stacks_v1(new_model));
    remove_tree(dir.substr(0, dir.rfind('/')));
}

namespace {

/// Set in the environment of the writer process the kill test starts.
constexpr const char *WRITER_ENV = "SBRT_TEST_ATOMIC_WRITER";

/// The writer process: this test binary exec'ed with WRITER_ENV =
/// "seed size history_bytes directory", run here before main() and before
/// any thread, writes model_with_seed(seed, size) to `directory` under the
/// file size limit its parent set (RLIMIT_FSIZE survives exec). The first
/// write past the limit raises SIGXFSZ, turned into SIGKILL: the process
/// dies at exactly that byte of that file, nothing of it cleaned up.
void run_writer(const char *spec)
{
    unsigned seed = 0;
    int size = 0;
    size_t history = 0;
    int at = 0;
    if (std::sscanf(spec, "%u %d %zu %n", &seed, &size, &history, &at) != 3)
        _exit(2);
    std::signal(SIGXFSZ, [](int) { kill(getpid(), SIGKILL); });
    try {
        write_sbrt(spec + at, model_with_seed(seed, size), std::string(history, 'h'));
    }
    catch (...) {
        _exit(3);
    }
    _exit(0);
}

/// Where this process is such a writer, it writes and exits here.
const bool writer_checked = [] {
    if (const char *spec = std::getenv(WRITER_ENV))
        run_writer(spec);
    return true;
}();

/// Writes model_with_seed(seed, size) to `dir` with a history of
/// `history` bytes in a fresh process that may write `limit` bytes into any
/// one file; returns its pid, `status` its wait status. Between fork and
/// exec the child calls only async-signal-safe functions: this process may
/// hold GL threads from other tests.
pid_t write_in_child(const std::string &dir, unsigned seed, int size, size_t history,
                     rlim_t limit, int &status)
{
    std::string spec = std::string(WRITER_ENV) + "=" + std::to_string(seed) + " " +
                       std::to_string(size) + " " + std::to_string(history) + " " + dir;
    std::vector<char *> env;
    for (char **e = environ; *e; ++e)
        if (std::string(*e).rfind(std::string(WRITER_ENV) + "=", 0) != 0)
            env.push_back(*e);
    env.push_back(spec.data());
    env.push_back(nullptr);
    rlimit fsize;
    if (getrlimit(RLIMIT_FSIZE, &fsize) == 0 && fsize.rlim_max != RLIM_INFINITY)
        limit = std::min(limit, fsize.rlim_max);
    fsize.rlim_cur = fsize.rlim_max = limit;
    char name[] = "sbrt_unit_tests";
    char *argv[] = {name, nullptr};
    const pid_t child = fork();
    if (child == 0) {
        if (setrlimit(RLIMIT_FSIZE, &fsize) == 0)
            execve("/proc/self/exe", argv, env.data());
        _exit(127);
    }
    status = -1;
    if (child > 0)
        waitpid(child, &status, 0);
    return child;
}

std::set<std::string> entries(const std::string &dir)
{
    std::set<std::string> names;
    for (const auto &e : std::filesystem::directory_iterator(dir))
        names.insert(e.path().filename().string());
    return names;
}

std::string file_text(const std::string &path)
{
    const std::vector<uint8_t> bytes = read_file_bytes(path);
    return std::string(bytes.begin(), bytes.end());
}

/// The files of an SBRT directory, name -> content.
std::vector<std::pair<std::string, std::string>> snapshot(const std::string &dir)
{
    std::vector<std::pair<std::string, std::string>> files;
    for (const std::string &name : entries(dir))
        files.emplace_back(name, file_text(dir + "/" + name));
    return files;
}

} // namespace

TEST(AtomicWrite, KilledMidWriteLeavesNoTargetOrTheWholeOldOne)
{
    const std::string parent = sbrt_test::temp_dir("kill");
    const std::string dir = parent + "/m";
    const unsigned new_seed = 4;
    const int new_size = 8;
    const Model new_model = model_with_seed(new_seed, new_size);
    const std::string stacks = [&] {
        const auto bytes = encode_stacks_v2(new_model);
        return std::string(bytes.begin(), bytes.end());
    }();
    // as a kill finds it: the header is written last, over zeros
    std::string streamed = stacks;
    std::fill_n(streamed.begin(), STACKS_V2_HEADER_SIZE, '\0');
    const size_t history = 3 * stacks.size();
    // stacks, header, cats, hist are written in this order: under a limit
    // below the size of stacks the kill lands in stacks; from it on, in
    // hist, the last file before the commit, once header and cats are whole
    ASSERT_LT(encode_header(new_model).size(), stacks.size());
    ASSERT_LT(encode_cats(new_model).size(), stacks.size());
    const size_t n = stacks.size();
    const std::vector<size_t> in_stacks = {0, 1, STACKS_V2_HEADER_SIZE - 1, STACKS_V2_HEADER_SIZE,
                                           n / 2, n - 1};
    const std::vector<size_t> in_hist = {n, n + 1, history / 2, history - 1};

    // a write that runs to its end: the new SBRT and no temporary left
    // (the control: the writer process does write)
    int status = 0;
    write_in_child(dir, new_seed, new_size, history, RLIM_INFINITY, status);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
    EXPECT_EQ(entries(parent), std::set<std::string>{"m"});
    EXPECT_EQ(file_text(dir + "/stacks"), stacks);
    EXPECT_EQ(file_text(dir + "/hist"), std::string(history, 'h'));
    remove_tree(dir);

    for (const bool had_old : {false, true}) {
        if (had_old)
            write_sbrt(dir, model_with_seed(3, 6), "old\n");
        const auto old_files = had_old ? snapshot(dir) : decltype(snapshot(dir)){};
        for (const bool hist_killed : {false, true})
            for (const size_t limit : hist_killed ? in_hist : in_stacks) {
                const std::string what = std::string(had_old ? "over an old SBRT" : "new") +
                                         ", killed at byte " + std::to_string(limit) +
                                         (hist_killed ? " of hist" : " of stacks");
                const pid_t child =
                    write_in_child(dir, new_seed, new_size, history, limit, status);
                ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
                    << what << ": status " << status;
                // the destination: absent, or the whole old one
                std::set<std::string> names = entries(parent);
                if (!had_old)
                    EXPECT_FALSE(std::filesystem::exists(dir)) << what;
                else {
                    ASSERT_EQ(names.erase("m"), 1u) << what;
                    EXPECT_EQ(snapshot(dir), old_files) << what;
                    EXPECT_EQ(encode_stacks_v1(read_sbrt(dir)),
                              encode_stacks_v1(model_with_seed(3, 6)))
                        << what;
                }
                // what is left: one hidden sibling of the killed process,
                // which listings skip, holding the write up to the kill
                ASSERT_EQ(names.size(), 1u) << what;
                const std::string temp = *names.begin();
                EXPECT_EQ(temp[0], '.') << what << ": " << temp;
                EXPECT_NE(temp.find(std::to_string(child)), std::string::npos) << temp;
                const std::string written = parent + "/" + temp;
                if (hist_killed) {
                    EXPECT_EQ(file_text(written + "/stacks"), stacks) << what;
                    EXPECT_EQ(file_text(written + "/hist"), std::string(limit, 'h')) << what;
                }
                else {
                    EXPECT_EQ(file_text(written + "/stacks"), streamed.substr(0, limit))
                        << what;
                    EXPECT_FALSE(std::filesystem::exists(written + "/header")) << what;
                }
                // a fresh temporary is never swept (see the next test)
                remove_tree(written);
            }
    }
    // and a later write replaces the old SBRT whole
    write_sbrt(dir, new_model, "new\n");
    EXPECT_EQ(file_text(dir + "/stacks"), stacks);
    EXPECT_EQ(entries(parent), std::set<std::string>{"m"});
    remove_tree(parent);
}

TEST(AtomicWrite, TheNextWriteSweepsOnlyOldTemporariesOfGoneProcesses)
{
    namespace fs = std::filesystem;
    const std::string parent = sbrt_test::temp_dir("sweep");
    const pid_t gone = fork();
    if (gone == 0)
        _exit(0);
    ASSERT_GT(gone, 0);
    waitpid(gone, nullptr, 0);
    const std::string dead = std::to_string(gone), live = std::to_string(getppid());
    const auto hours_ago = fs::file_time_type::clock::now() - std::chrono::hours(2);
    auto make = [&](const std::string &name, bool old) {
        const fs::path dir = parent + "/" + name;
        fs::create_directory(dir);
        const fs::path file = dir / "stacks";
        { std::ofstream(file) << "partial"; }
        if (old) {
            fs::last_write_time(file, hours_ago);
            fs::last_write_time(dir, hours_ago);
        }
    };
    make(".m.tmp." + dead, true);   // a killed writer's, long ago: swept
    make(".m.tmp." + live, true);   // a live process's: kept
    make(".m.tmp.x" + dead, true);  // not a pid: kept
    make(".n.tmp." + dead, true);   // another SBRT's: kept
    make(".m.old." + dead, true);   // maybe the only copy: kept
    write_sbrt(parent + "/m", model_with_seed(3, 6), "new\n");
    EXPECT_EQ(entries(parent),
              (std::set<std::string>{"m", ".m.tmp." + live, ".m.tmp.x" + dead,
                                     ".n.tmp." + dead, ".m.old." + dead}));
    // one written into within the hour may be a writer on another host
    remove_tree(parent + "/m");
    make(".m.tmp." + dead, false);
    write_sbrt(parent + "/m", model_with_seed(3, 6), "new\n");
    EXPECT_TRUE(fs::exists(parent + "/.m.tmp." + dead));
    remove_tree(parent);
}

// What r3.sbrt.manage stages through AtomicDirectory (issue 28, reuse):
// a copy of another directory file by file, rename and removal.

TEST(AtomicWrite, CopyFileStagesAWholeCopyOfAnotherDirectory)
{
    const std::string parent = sbrt_test::temp_dir("copy");
    const std::string source = parent + "/source", target = parent + "/target";
    write_sbrt(source, model_with_seed(5, 7), "source history\n");
    write_sbrt(target, model_with_seed(6, 5), "replaced\n");
    for (int round = 0; round < 2; ++round) { // onto the old target, then onto a copy
        const MemberDirectory from(source);
        AtomicDirectory staged(target);
        for (const std::string &name : from.member_names())
            staged.copy_file(name, from.open_regular(name), from.member_path(name));
        staged.commit();
        EXPECT_EQ(snapshot(target), snapshot(source));
    }
    EXPECT_EQ(entries(parent), (std::set<std::string>{"source", "target"}));
    remove_tree(parent);
}

TEST(AtomicWrite, CopyFileOfALargeFileIsWhole)
{
    const std::string parent = sbrt_test::temp_dir("bigcopy");
    std::string bytes(3 << 20, '\0'); // past one buffer of the fallback
    for (size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = char(i * 2654435761u >> 24);
    {
        std::ofstream(parent + "/big", std::ios::binary) << bytes;
    }
    AtomicDirectory staged(parent + "/m");
    staged.copy_file("big", open_regular_file(parent + "/big"), "big");
    staged.commit();
    EXPECT_EQ(file_text(parent + "/m/big"), bytes);
    remove_tree(parent);
}

TEST(AtomicWrite, Issue28FileNamesStayInTheTemporaryDirectory)
{
    const std::string parent = sbrt_test::temp_dir("names");
    AtomicDirectory staged(parent + "/sub/m");
    for (const std::string name : {"../escaped", "..", ".", "", "a/b"})
        EXPECT_THROW(staged.write_file(name, std::string("x")), Error) << name;
    {
        std::ofstream(parent + "/source") << "source";
    }
    for (const std::string name : {"../escaped", "../../escaped"})
        EXPECT_THROW(staged.copy_file(name, open_regular_file(parent + "/source"), "source"),
                     Error)
            << name;
    EXPECT_FALSE(std::filesystem::exists(parent + "/sub/escaped"));
    EXPECT_FALSE(std::filesystem::exists(parent + "/escaped"));
    remove_tree(parent);
}

TEST(AtomicWrite, ReplaceDirectoryMovesOneDirectoryOntoAnother)
{
    const std::string parent = sbrt_test::temp_dir("replace");
    write_sbrt(parent + "/a", model_with_seed(1, 6), "a\n");
    const auto a = snapshot(parent + "/a");
    // onto a free name: a rename
    replace_directory(parent + "/a", parent + "/b");
    EXPECT_EQ(entries(parent), std::set<std::string>{"b"});
    EXPECT_EQ(snapshot(parent + "/b"), a);
    // onto an existing one: its content goes, nothing hidden stays
    write_sbrt(parent + "/c", model_with_seed(2, 7), "c\n");
    const auto c = snapshot(parent + "/c");
    replace_directory(parent + "/c", parent + "/b");
    EXPECT_EQ(entries(parent), std::set<std::string>{"b"});
    EXPECT_EQ(snapshot(parent + "/b"), c);
    // a missing source: an error, the target as it was
    EXPECT_THROW(replace_directory(parent + "/none", parent + "/b"), Error);
    EXPECT_EQ(snapshot(parent + "/b"), c);
    remove_tree(parent);
}

TEST(AtomicWrite, RemoveDirectoryLeavesNothing)
{
    const std::string parent = sbrt_test::temp_dir("remove");
    write_sbrt(parent + "/a", model_with_seed(1, 6), "a\n");
    write_sbrt(parent + "/b", model_with_seed(1, 6), "b\n");
    remove_directory(parent + "/a");
    EXPECT_EQ(entries(parent), std::set<std::string>{"b"});
    EXPECT_THROW(remove_directory(parent + "/a"), Error);
    remove_tree(parent);
}
