// "Did you mean": the known name an unknown one was probably meant to be, for the messages
// about unknown fields of scene files (scene_reader.cpp) and of the Lua module's tables
// (bindings/lua/src/args.cpp), and so of JavaScript's definitions, which are scene files'.
// The rule, worded once:
//
// - An edit is a character inserted, deleted or replaced, or two neighbours swapped
//   ("frcition" is one edit from "friction"); letters are compared without their case, so
//   "snapdown" is no edit from "snapDown" and "SNAPDOWN" none either.
// - A known name is suggested if it is at most two edits away, and fewer edits than the
//   shorter of the two names has characters: "z" is one edit from "x", but it is not a
//   typo of it.
// - Of several, the one with the fewest edits wins; then the one with the fewest counting
//   case; then the first in the list of known names.
//
// No allocation and nothing to destroy: the Lua module words its errors in frames that a
// Lua error may leave by longjmp.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

namespace jostle {

/// The most edits a suggestion may be from the name given.
inline constexpr std::size_t kMaxSuggestionEdits = 2;

namespace suggest_detail {

inline constexpr std::size_t kFar = kMaxSuggestionEdits + 1;
/// Known names are short: longer ones are never suggested (nor a name far longer).
inline constexpr std::size_t kLongest = 64;

constexpr char lower(char c) {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

constexpr std::size_t smallest(std::size_t a, std::size_t b) {
    return a < b ? a : b;
}

} // namespace suggest_detail

/// The edits between `a` and `b` (the rule above: optimal string alignment), letters
/// compared with their case or without it; kMaxSuggestionEdits + 1 for any number above
/// kMaxSuggestionEdits.
constexpr std::size_t nameEdits(std::string_view a, std::string_view b, bool ignoreCase) {
    using namespace suggest_detail;
    if (a.size() > b.size() + kMaxSuggestionEdits || b.size() > a.size() + kMaxSuggestionEdits ||
        a.size() >= kLongest || b.size() >= kLongest)
        return kFar;
    auto same = [&](char x, char y) { return ignoreCase ? lower(x) == lower(y) : x == y; };
    // Three rows of the table of edits between the first i characters of a and the first
    // j of b: row i is rows[(i + 1) % 3], beside the two above it.
    std::size_t rows[3][kLongest + 1] = {};
    for (std::size_t j = 0; j <= b.size(); ++j)
        rows[1][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t* row = rows[(i + 1) % 3];
        std::size_t* above = rows[i % 3];
        std::size_t* two = rows[(i + 2) % 3];
        row[0] = i;
        std::size_t least = row[0];
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t replace = above[j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1);
            std::size_t best = smallest(replace, smallest(above[j], row[j - 1]) + 1);
            if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
                best = smallest(best, two[j - 2] + 1);
            row[j] = best;
            least = smallest(least, best);
        }
        if (least > kMaxSuggestionEdits)
            return kFar; // no later row has fewer
    }
    const std::size_t edits = rows[(a.size() + 1) % 3][b.size()];
    return edits > kMaxSuggestionEdits ? kFar : edits;
}

/// The known name nearest to `unknown` under the rule above, from the names offered to
/// consider() in their order.
class NearestName {
public:
    constexpr explicit NearestName(std::string_view unknown) : unknown_(unknown) {}

    constexpr void consider(std::string_view known) {
        using namespace suggest_detail;
        const std::size_t edits = nameEdits(unknown_, known, true);
        if (edits > kMaxSuggestionEdits || edits >= smallest(unknown_.size(), known.size()))
            return;
        const std::size_t caseEdits = nameEdits(unknown_, known, false);
        if (best_.empty() || edits < edits_ || (edits == edits_ && caseEdits < caseEdits_)) {
            best_ = known;
            edits_ = edits;
            caseEdits_ = caseEdits;
        }
    }

    /// The suggestion, or empty if no known name is near enough.
    constexpr std::string_view name() const { return best_; }

private:
    std::string_view unknown_;
    std::string_view best_;
    std::size_t edits_ = suggest_detail::kFar;
    std::size_t caseEdits_ = suggest_detail::kFar;
};

/// What a message about an unknown field adds for a suggestion, in every language:
/// ` (did you mean "snapDown"?)`; "" for none. Written into `out` (cut to `size` bytes).
inline void didYouMean(std::string_view suggestion, char* out, std::size_t size) {
    if (size == 0)
        return;
    out[0] = '\0';
    if (!suggestion.empty())
        std::snprintf(out, size, " (did you mean \"%.*s\"?)", static_cast<int>(suggestion.size()),
                      suggestion.data());
}

/// The same as a string.
inline std::string didYouMean(std::string_view suggestion) {
    char text[suggest_detail::kLongest + 32];
    didYouMean(suggestion, text, sizeof text);
    return text;
}

} // namespace jostle
