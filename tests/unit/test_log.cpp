// SPDX-License-Identifier: MIT
// log::Logger into a pipe: the sd-daemon priority prefixes journald reads when stderr is the
// journal stream ($JOURNAL_STREAM), and plain lines on a pipe or a terminal otherwise.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>

#include "raypoint/service/log.hpp"

namespace {

using raypoint::daemon::log::Level;
using raypoint::daemon::log::Logger;

class Pipe {
  public:
    Pipe() {
        if (::pipe2(fds_, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
    }
    ~Pipe() {
        ::close(fds_[0]);
        if (fds_[1] >= 0) ::close(fds_[1]);
    }
    Pipe(const Pipe&) = delete;
    Pipe& operator=(const Pipe&) = delete;

    int write_end() const { return fds_[1]; }
    // Closes the write end and returns everything written.
    std::string drain() {
        ::close(fds_[1]);
        fds_[1] = -1;
        std::string text;
        char buffer[256];
        for (ssize_t size; (size = ::read(fds_[0], buffer, sizeof(buffer))) > 0;)
            text.append(buffer, static_cast<std::size_t>(size));
        return text;
    }

  private:
    int fds_[2] = {-1, -1};
};

// $JOURNAL_STREAM's "device:inode" for `fd`, as systemd would set it for a journal stream.
std::string stream_id(int fd) {
    struct stat status {};
    if (::fstat(fd, &status) != 0) throw std::runtime_error("fstat failed");
    return std::to_string(status.st_dev) + ":" + std::to_string(status.st_ino);
}

TEST(Logger, TheJournalStreamGetsSdDaemonPriorityPrefixes) {
    Pipe pipe;
    ::setenv("JOURNAL_STREAM", stream_id(pipe.write_end()).c_str(), 1);
    Logger logger(pipe.write_end());
    ::unsetenv("JOURNAL_STREAM");
    EXPECT_TRUE(logger.prefixed());
    logger.set_max_level(Level::debug);
    logger.write(Level::error, "camera /dev/video0 gone");
    logger.write(Level::warning, "uinput slow");
    logger.write(Level::info, "tracking");
    logger.write(Level::debug, "frame 12");
    EXPECT_EQ(pipe.drain(),
              "<3>camera /dev/video0 gone\n<4>uinput slow\n<6>tracking\n<7>frame 12\n");
}

TEST(Logger, UnprefixedWritesThePlainLine) {
    Pipe pipe;
    Logger logger(pipe.write_end(), false);
    logger.write(Level::error, "no camera");
    logger.write(Level::info, "ready");
    EXPECT_EQ(pipe.drain(), "no camera\nready\n");
}

TEST(Logger, APipeGetsPlainLines) {
    Pipe pipe;
    ::unsetenv("JOURNAL_STREAM");
    Logger logger(pipe.write_end());
    EXPECT_FALSE(logger.prefixed());
    logger.write(Level::error, "no camera");
    EXPECT_EQ(pipe.drain(), "no camera\n");
}

TEST(Logger, AnotherFilesJournalStreamIsNotOurs) {
    Pipe pipe;
    Pipe journal;
    // A service's child whose stderr was redirected to a pipe inherits $JOURNAL_STREAM.
    EXPECT_FALSE(raypoint::daemon::log::is_journal_stream(pipe.write_end(),
                                                          stream_id(journal.write_end()).c_str()));
    EXPECT_TRUE(raypoint::daemon::log::is_journal_stream(pipe.write_end(),
                                                         stream_id(pipe.write_end()).c_str()));
    EXPECT_FALSE(raypoint::daemon::log::is_journal_stream(pipe.write_end(), "garbage"));
    EXPECT_FALSE(raypoint::daemon::log::is_journal_stream(pipe.write_end(), "12:"));
    EXPECT_FALSE(raypoint::daemon::log::is_journal_stream(pipe.write_end(), nullptr));
}

TEST(Logger, DebugIsDroppedUnlessAsked) {
    Pipe pipe;
    Logger logger(pipe.write_end(), true);
    EXPECT_EQ(logger.max_level(), Level::info);
    logger.write(Level::debug, "frame 1");
    logger.write(Level::info, "shown");
    logger.set_max_level(Level::warning);
    logger.write(Level::info, "hidden");
    logger.write(Level::warning, "kept");
    EXPECT_EQ(pipe.drain(), "<6>shown\n<4>kept\n");
}

TEST(Logger, ANewlineInTheMessageStaysOneLine) {
    Pipe pipe;
    Logger logger(pipe.write_end(), true);
    logger.write(Level::error, "first\n<6>second");
    EXPECT_EQ(pipe.drain(), "<3>first <6>second\n");
}

TEST(Logger, ATerminalGetsNoPrefix) {
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0)
        GTEST_SKIP() << "no pseudo-terminal here";
    const int terminal = ::open(::ptsname(master), O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (terminal < 0) GTEST_SKIP() << "cannot open the pseudo-terminal";
    const Logger logger(terminal);
    EXPECT_FALSE(logger.prefixed());
    ::close(terminal);
    ::close(master);
}

TEST(Logger, FreeFunctionsWriteToStderr) {
    Pipe pipe;
    const int saved = ::dup(STDERR_FILENO);
    ::dup2(pipe.write_end(), STDERR_FILENO);
    // stderr_logger() decided on its prefix at first use; whatever it decided, the line is there.
    // (tests/cli/test_journal_priority.sh checks the decision on a real process.)
    raypoint::daemon::log::warning("to stderr");
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
    const std::string text = pipe.drain();
    EXPECT_TRUE(text == "<4>to stderr\n" || text == "to stderr\n") << text;
}

}  // namespace
