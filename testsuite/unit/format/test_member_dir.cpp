/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The SBRT reader opens members as untrusted input (issue 28,
 *            items 1 and 2): a FIFO, a symbolic link or a directory as
 *            stacks or cats is refused at once with its name, never read
 *            through or waited on
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <csignal>
#include <cstdio>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "builders/voxel_builder.hpp"
#include "format/atomic_dir.hpp"
#include "format/format.hpp"
#include "format/member_dir.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace {

/// How a read in a child process ended: a read that waits on a FIFO
/// would hang the test binary, so it runs apart and is killed after 5 s.
struct Outcome {
    bool hung = false;
    bool threw = false;
    std::string message; ///< of the sbrt::Error
};

Outcome outcome_of(const std::function<void()> &read)
{
    int pipe_fds[2];
    if (pipe(pipe_fds) != 0)
        return {true, false, "pipe failed"};
    const pid_t child = fork();
    if (child == 0) {
        close(pipe_fds[0]);
        int code = 1;
        std::string message;
        try {
            read();
        }
        catch (const Error &e) {
            code = 0;
            message = e.what();
        }
        if (!message.empty() && write(pipe_fds[1], message.data(), message.size()) < 0)
            code = 2;
        _exit(code);
    }
    close(pipe_fds[1]);
    Outcome outcome;
    int status = 0;
    const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (waitpid(child, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > limit) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
            outcome.hung = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    char buffer[4096];
    for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0;)
        outcome.message.append(buffer, size_t(n));
    close(pipe_fds[0]);
    outcome.threw = !outcome.hung && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    return outcome;
}

/// A valid SBRT `parent/m`, and the path of its member `member`.
struct Sbrt {
    std::string parent, dir;
    std::string member(const std::string &name) const { return dir + "/" + name; }
};

Sbrt valid_sbrt(const std::string &tag)
{
    Sbrt s;
    s.parent = sbrt_test::temp_dir(tag);
    s.dir = s.parent + "/m";
    write_sbrt(s.dir, sbrt_test::build_model(sbrt_test::random_voxels(7, 6, 5, 20)), "hist\n");
    return s;
}

/// Expects `read` to throw at once, its message naming `path` and `kind`.
void expect_refused(const std::function<void()> &read, const std::string &path,
                    const std::string &kind)
{
    const Outcome outcome = outcome_of(read);
    ASSERT_FALSE(outcome.hung) << path << ": the read waited (killed after 5 s)";
    ASSERT_TRUE(outcome.threw) << path << ": read without an sbrt::Error";
    EXPECT_NE(outcome.message.find(path + ": " + kind), std::string::npos)
        << outcome.message;
    EXPECT_NE(outcome.message.find("not a regular file"), std::string::npos)
        << outcome.message;
}

void replace_by_fifo(const std::string &path)
{
    std::filesystem::remove(path);
    ASSERT_EQ(mkfifo(path.c_str(), 0644), 0);
}

} // namespace

TEST(MemberDirectory, Issue28FifoAsStacksOrCatsIsRefusedWithoutWaiting)
{
    for (const std::string name : {"stacks", "cats"}) {
        const Sbrt s = valid_sbrt("fifo");
        replace_by_fifo(s.member(name));
        expect_refused([&] { read_sbrt(s.dir); }, s.member(name), "a FIFO");
        if (name == "stacks")
            expect_refused([&] { stacks_file_info(s.dir); }, s.member(name), "a FIFO");
        expect_refused([&] { read_file_bytes(s.member(name)); }, s.member(name), "a FIFO");
        remove_tree(s.parent);
    }
}

TEST(MemberDirectory, Issue28SymbolicLinkAsMemberIsNotFollowed)
{
    // links to the valid files of another SBRT: read through, they would
    // give a model; an SBRT of another mapset could so read any file
    const Sbrt other = valid_sbrt("target");
    for (const std::string name : {"stacks", "cats"}) {
        const Sbrt s = valid_sbrt("link");
        std::filesystem::remove(s.member(name));
        std::filesystem::create_symlink(other.member(name), s.member(name));
        expect_refused([&] { read_sbrt(s.dir); }, s.member(name), "a symbolic link");
        if (name == "stacks")
            expect_refused([&] { stacks_file_info(s.dir); }, s.member(name),
                           "a symbolic link");
        remove_tree(s.parent);
    }
    remove_tree(other.parent);
}

TEST(MemberDirectory, Issue28DirectoryAsMemberIsRefused)
{
    for (const std::string name : {"stacks", "cats"}) {
        const Sbrt s = valid_sbrt("subdir");
        std::filesystem::remove(s.member(name));
        std::filesystem::create_directory(s.member(name));
        expect_refused([&] { read_sbrt(s.dir); }, s.member(name), "a directory");
        remove_tree(s.parent);
    }
}

TEST(MemberDirectory, Issue28LinkedSbrtDirectoryIsRefused)
{
    const Sbrt s = valid_sbrt("linkdir");
    const std::string link = s.parent + "/linked";
    std::filesystem::create_directory_symlink(s.dir, link);
    const Outcome outcome = outcome_of([&] { read_sbrt(link); });
    ASSERT_TRUE(outcome.threw);
    EXPECT_NE(outcome.message.find(link + ": a symbolic link, not a directory"),
              std::string::npos)
        << outcome.message;
    EXPECT_NO_THROW(read_sbrt(s.dir));
    remove_tree(s.parent);
}

TEST(MemberDirectory, MissingCatsIsNoErrorAndMissingStacksIsNamed)
{
    const Sbrt s = valid_sbrt("missing");
    std::filesystem::remove(s.member("cats"));
    EXPECT_NO_THROW(read_sbrt(s.dir));
    std::filesystem::remove(s.member("stacks"));
    const Outcome outcome = outcome_of([&] { read_sbrt(s.dir); });
    ASSERT_TRUE(outcome.threw);
    EXPECT_NE(outcome.message.find(s.member("stacks") + ": missing"), std::string::npos)
        << outcome.message;
    remove_tree(s.parent);
}

TEST(MemberDirectory, OnlyNamesOfEntriesAreMembers)
{
    const Sbrt s = valid_sbrt("names");
    const MemberDirectory dir(s.dir);
    EXPECT_EQ(dir.member_names(),
              (std::vector<std::string>{"cats", "colors", "header", "hist", "ranges", "stacks",
                                        "tops"}));
    for (const std::string name : {"", ".", "..", "../m/stacks", "/etc/passwd"})
        EXPECT_THROW(dir.open_regular(name), Error) << name;
    EXPECT_FALSE(dir.open_regular_if_present("none").has_value());
    const std::vector<uint8_t> hist = read_all(dir.open_regular("hist"), "hist");
    EXPECT_EQ(std::string(hist.begin(), hist.end()), "hist\n");
    remove_tree(s.parent);
}
