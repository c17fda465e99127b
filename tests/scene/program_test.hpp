// The jostle program run as a user runs it, for the tests of its commands: a folder of
// its own for each test, files written into it, and runs that capture the exit status
// and both outputs.
#pragma once

#include <gtest/gtest.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace jostle::testing {

/// What a run of the program gave.
struct ProgramResult {
    int status = -1; ///< the exit status; -1 if it did not exit normally
    std::string out;
    std::string err;
};

inline std::string readAll(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// A path for the shell, in single quotes.
/// Whether this machine gives out pseudo-terminals (a container may have none): tests of
/// what a terminal shows are skipped where it does not.
inline bool pseudoTerminalsWork() {
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    const bool works = master >= 0 && ::grantpt(master) == 0 && ::unlockpt(master) == 0;
    if (master >= 0)
        ::close(master);
    return works;
}

#define JOSTLE_SKIP_WITHOUT_A_TERMINAL()                                                           \
    if (!jostle::testing::pseudoTerminalsWork())                                                   \
    GTEST_SKIP() << "no pseudo-terminal on this machine"

inline std::string quote(const std::string& text) {
    return "'" + text + "'";
}

/// What a terminal shows on its last line after receiving `text`: each "\r" goes back
/// to the line's start, and what follows is written over what was there. Without the
/// spaces at its end.
inline std::string lastLineShown(const std::string& text) {
    std::string line;
    std::size_t column = 0;
    for (const char c :
         text.substr(text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1)) {
        if (c == '\r') {
            column = 0;
            continue;
        }
        if (column < line.size())
            line[column] = c;
        else
            line += c;
        ++column;
    }
    return line.substr(0, line.find_last_not_of(' ') + 1);
}

/// A fixture with a temporary folder, removed after the test; JOSTLE_EXE names the program.
class ProgramTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() /
               ("jostle_" + std::string(test->test_suite_name()) + "_" +
                std::to_string(::getpid()) + "_" + test->name());
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    /// Writes `text` to the file `name` in the test's folder; returns its path.
    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(path(name), std::ios::binary) << text;
        return path(name);
    }

    /// Runs `jostle ARGS`, capturing the exit status, stdout and stderr.
    ProgramResult run(const std::string& args) {
        std::string redirection = ">";
        redirection += quote(path("stdout"));
        return run(args, redirection);
    }

    /// Runs `jostle ARGS` with stdout sent where the shell's `redirection` says
    /// (">/dev/full", ">&-" to close it), capturing the exit status and stderr.
    ProgramResult run(const std::string& args, const std::string& redirection) {
        return runShell(quote(JOSTLE_EXE) + " " + args, redirection);
    }

    /// Runs `jostle ARGS` with standard input a pipe from the shell command `producer`.
    ProgramResult runPiped(const std::string& producer, const std::string& args) {
        std::string redirection = ">";
        redirection += quote(path("stdout"));
        return runShell("(" + producer + ") | " + quote(JOSTLE_EXE) + " " + args, redirection);
    }

    /// Runs the shell command `command` with its stdout sent where `redirection` says,
    /// capturing its exit status, stdout and stderr.
    ProgramResult runShell(const std::string& command, const std::string& redirection) {
        std::filesystem::remove(path("stdout"));
        const std::string redirected = command + " " + redirection + " 2>" + quote(path("stderr"));
        const int raw = std::system(redirected.c_str());
        ProgramResult result;
        if (raw != -1 && WIFEXITED(raw))
            result.status = WEXITSTATUS(raw);
        result.out = readAll(path("stdout"));
        result.err = readAll(path("stderr"));
        return result;
    }

    /// Runs `jostle ARGS` with standard error on a terminal (a pseudo-terminal), and
    /// standard output to a file or, with `stdoutToo`, on that terminal as well. `err` is
    /// all the terminal received (line ends as "\r\n"), `out` the file.
    ProgramResult runOnTerminal(const std::string& args, bool stdoutToo = false) {
        ProgramResult result;
        const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
        if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) {
            ADD_FAILURE() << "no pseudo-terminal: " << std::strerror(errno);
            return result;
        }
        // The terminal's end is opened before the fork, so that it stays open until the
        // program ends, and reading the other end ends there.
        const int terminal = ::open(::ptsname(master), O_RDWR | O_NOCTTY);
        if (terminal < 0) {
            ADD_FAILURE() << "cannot open the pseudo-terminal: " << std::strerror(errno);
            ::close(master);
            return result;
        }
        const std::string command = quote(JOSTLE_EXE) + " " + args;
        const std::string out = path("stdout");
        std::filesystem::remove(out);
        const pid_t child = ::fork();
        if (child == 0) {
            const int file = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            ::dup2(stdoutToo ? terminal : file, STDOUT_FILENO);
            ::dup2(terminal, STDERR_FILENO);
            ::close(master);
            ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
            ::_exit(127);
        }
        ::close(terminal);
        char buffer[4096];
        for (ssize_t n; (n = ::read(master, buffer, sizeof buffer)) > 0;)
            result.err.append(buffer, static_cast<std::size_t>(n));
        ::close(master);
        int raw = 0;
        if (child > 0 && ::waitpid(child, &raw, 0) == child && WIFEXITED(raw))
            result.status = WEXITSTATUS(raw);
        result.out = readAll(out);
        return result;
    }

private:
    std::filesystem::path dir_;
};

} // namespace jostle::testing
