// The progress of a long run, for a person watching it: "jostle run: step 1200 of 5000
// (24%)" on standard error, redrawn in place at most a few times a second and erased at
// the end. Only when standard error is a terminal, so that nothing of it reaches a file,
// a pipe or a test; and not while standard output writes to the same screen (a trace to
// the terminal), whose lines it would break.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

namespace jostle::cli {

class Progress {
public:
    /// Progress of `total` steps, labelled `label` ("jostle run"); shown only if standard
    /// error is a terminal and `stdoutBusy` (standard output written while stepping) is
    /// false or standard output is not a terminal. Shows step 0 at once.
    Progress(std::string label, std::int64_t total, bool stdoutBusy);
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    ~Progress() { erase(); }

    /// `done` steps of the total are done: redrawn if the last drawing is old enough.
    void update(std::int64_t done) {
        if (shown_)
            redraw(done, false);
    }
    /// Removes the line, leaving the cursor at its start; nothing more is drawn after.
    void erase();

private:
    void redraw(std::int64_t done, bool now);

    std::string label_;
    std::int64_t total_;
    bool shown_;
    std::size_t drawn_ = 0; ///< the length of the line on the screen
    std::chrono::steady_clock::time_point last_;
};

} // namespace jostle::cli
