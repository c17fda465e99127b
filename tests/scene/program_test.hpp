// The jostle program run as a user runs it, for the tests of its commands: a folder of
// its own for each test, files written into it, and runs that capture the exit status
// and both outputs.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
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
inline std::string quote(const std::string& text) {
    return "'" + text + "'";
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
    ProgramResult run(const std::string& args) { return runShell(quote(JOSTLE_EXE) + " " + args); }

    /// Runs `jostle ARGS` with standard input a pipe from the shell command `producer`.
    ProgramResult runPiped(const std::string& producer, const std::string& args) {
        return runShell("(" + producer + ") | " + quote(JOSTLE_EXE) + " " + args);
    }

private:
    /// Runs the shell command `command`, capturing its exit status, stdout and stderr.
    ProgramResult runShell(const std::string& command) {
        const std::string redirected =
            command + " >" + quote(path("stdout")) + " 2>" + quote(path("stderr"));
        const int raw = std::system(redirected.c_str());
        ProgramResult result;
        if (raw != -1 && WIFEXITED(raw))
            result.status = WEXITSTATUS(raw);
        result.out = readAll(path("stdout"));
        result.err = readAll(path("stderr"));
        return result;
    }

    std::filesystem::path dir_;
};

} // namespace jostle::testing
