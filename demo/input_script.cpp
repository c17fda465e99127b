// Input scripts: see input_script.hpp.
#include "input_script.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace jostle::demo {

namespace {

[[noreturn]] void fail(int line, const std::string& part, const std::string& why) {
    throw std::runtime_error("--input, part " + std::to_string(line) + " \"" + part + "\": " + why);
}

Uint8 buttonFromName(const std::string& name) {
    if (name == "left")
        return SDL_BUTTON_LEFT;
    if (name == "middle")
        return SDL_BUTTON_MIDDLE;
    if (name == "right")
        return SDL_BUTTON_RIGHT;
    return 0;
}

} // namespace

std::vector<ScriptEvent> parseInputScript(const std::string& text) {
    std::string normalised = text;
    std::replace(normalised.begin(), normalised.end(), ';', '\n');
    std::istringstream lines(normalised);
    std::vector<ScriptEvent> events;
    std::string part;
    for (int number = 1; std::getline(lines, part); ++number) {
        const std::string line = part.substr(0, part.find('#'));
        std::istringstream words(line);
        std::string frameWord;
        if (!(words >> frameWord))
            continue;
        ScriptEvent event;
        std::size_t used = 0;
        try {
            event.frame = std::stoi(frameWord, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != frameWord.size() || event.frame < 1)
            fail(number, part, "the frame must be a whole number from 1");
        std::string action;
        std::string name;
        if (!(words >> action >> name))
            fail(number, part, "expected FRAME ACTION ARGUMENT");
        const bool isKey = action.rfind("key-", 0) == 0;
        const bool isMove = action == "mouse-move";
        if (isKey) {
            event.scancode = SDL_GetScancodeFromName(name.c_str());
            if (event.scancode == SDL_SCANCODE_UNKNOWN)
                fail(number, part, "unknown key \"" + name + "\" (SDL's key names: Right, Space)");
        } else if (isMove) {
            // mouse-move X Y: X was read as the name.
            if (!(std::istringstream(name) >> event.x) || !(words >> event.y))
                fail(number, part, "expected mouse-move X Y");
        } else {
            event.button = buttonFromName(name);
            if (event.button == 0)
                fail(number, part, "unknown button \"" + name + "\" (left, middle or right)");
            if (!(words >> event.x >> event.y))
                fail(number, part, "expected " + action + " BUTTON X Y");
        }
        std::string extra;
        if (words >> extra)
            fail(number, part, "unexpected \"" + extra + "\"");
        using Kind = ScriptEvent::Kind;
        const auto add = [&events, &event](Kind kind) {
            event.kind = kind;
            events.push_back(event);
        };
        if (action == "key-down") {
            add(Kind::KeyDown);
        } else if (action == "key-up") {
            add(Kind::KeyUp);
        } else if (action == "key-press") {
            add(Kind::KeyDown);
            add(Kind::KeyUp);
        } else if (action == "mouse-down") {
            add(Kind::MouseDown);
        } else if (action == "mouse-up") {
            add(Kind::MouseUp);
        } else if (action == "mouse-click") {
            add(Kind::MouseDown);
            add(Kind::MouseUp);
        } else if (isMove) {
            add(Kind::MouseMove);
        } else {
            fail(number, part, "unknown action \"" + action + "\"");
        }
    }
    std::stable_sort(events.begin(), events.end(),
                     [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
    return events;
}

std::vector<ScriptEvent> loadInputScript(const std::string& fileOrText) {
    std::ifstream file(fileOrText);
    if (!file)
        return parseInputScript(fileOrText);
    std::ostringstream text;
    text << file.rdbuf();
    return parseInputScript(text.str());
}

void InputPlayer::pushFrame(int frame, SDL_Window* window) {
    const Uint32 windowId = SDL_GetWindowID(window);
    for (; next_ < events_.size() && events_[next_].frame <= frame; ++next_) {
        const ScriptEvent& script = events_[next_];
        SDL_Event event{};
        switch (script.kind) {
        case ScriptEvent::Kind::KeyDown:
        case ScriptEvent::Kind::KeyUp: {
            const bool down = script.kind == ScriptEvent::Kind::KeyDown;
            event.type = down ? SDL_KEYDOWN : SDL_KEYUP;
            event.key.windowID = windowId;
            event.key.state = down ? SDL_PRESSED : SDL_RELEASED;
            event.key.keysym.scancode = script.scancode;
            event.key.keysym.sym = SDL_GetKeyFromScancode(script.scancode);
            break;
        }
        case ScriptEvent::Kind::MouseDown:
        case ScriptEvent::Kind::MouseUp: {
            const bool down = script.kind == ScriptEvent::Kind::MouseDown;
            if (down)
                buttons_ |= SDL_BUTTON(script.button);
            else
                buttons_ &= ~SDL_BUTTON(script.button);
            event.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
            event.button.windowID = windowId;
            event.button.button = script.button;
            event.button.state = down ? SDL_PRESSED : SDL_RELEASED;
            event.button.clicks = 1;
            event.button.x = script.x;
            event.button.y = script.y;
            break;
        }
        case ScriptEvent::Kind::MouseMove:
            event.type = SDL_MOUSEMOTION;
            event.motion.windowID = windowId;
            event.motion.state = buttons_;
            event.motion.x = script.x;
            event.motion.y = script.y;
            break;
        }
        if (SDL_PushEvent(&event) < 0)
            throw std::runtime_error(std::string("--input: cannot push an event: ") +
                                     SDL_GetError());
    }
}

} // namespace jostle::demo
