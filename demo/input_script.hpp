// --input: a script of keyboard and mouse events by frame, so that a run can be driven
// without anyone at the keys (tests, demos). Each event becomes an SDL_Event pushed onto
// SDL's queue at the start of its frame, so that the demo handles it exactly as it handles
// one from the keyboard or the mouse. The format is in docs/demo.md.
#pragma once

#include <SDL.h>

#include <string>
#include <vector>

namespace jostle::demo {

struct ScriptEvent {
    enum class Kind { KeyDown, KeyUp, MouseDown, MouseUp, MouseMove };
    int frame = 0; ///< the frame (from 1) at whose start the event is pushed
    Kind kind = Kind::KeyDown;
    SDL_Scancode scancode = SDL_SCANCODE_UNKNOWN; ///< keys
    Uint8 button = 0;                             ///< mouse buttons
    int x = 0;                                    ///< mouse events, in window pixels
    int y = 0;
};

/// The events of `text`: lines (or `;`-separated parts) `FRAME ACTION ARGS...`, blank
/// lines and `#` comments ignored. A press or click is a down and an up in the same frame.
/// Sorted by frame, in their order within a frame. Throws std::runtime_error on a mistake.
std::vector<ScriptEvent> parseInputScript(const std::string& text);

/// The script in the file `fileOrText` if there is such a file, else `fileOrText` itself.
std::vector<ScriptEvent> loadInputScript(const std::string& fileOrText);

/// Plays a script into SDL's event queue, frame by frame.
class InputPlayer {
public:
    explicit InputPlayer(std::vector<ScriptEvent> events) : events_(std::move(events)) {}
    /// Pushes the events of `frame` (call once per frame, frames in order, before polling).
    void pushFrame(int frame, SDL_Window* window);

private:
    std::vector<ScriptEvent> events_;
    std::size_t next_ = 0;
    Uint32 buttons_ = 0; ///< the buttons the script holds down, for motion events
};

} // namespace jostle::demo
