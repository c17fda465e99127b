// The CSV trace: see trace.hpp.
#include "trace.hpp"

namespace jostle::cli {

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos)
        return text;
    std::string field = "\"";
    for (char c : text) {
        if (c == '"')
            field += '"'; // a quote inside a quoted field is doubled
        field += c;
    }
    return field + "\"";
}

void writeTraceHeader(std::FILE* out) {
    std::fputs("step,id,x,y,vx,vy\n", out);
}

void writeTraceRows(std::FILE* out, std::int64_t step, const World& world,
                    std::span<const TracedBody> bodies) {
    for (const TracedBody& traced : bodies) {
        const Vec2 p = world.position(traced.body);
        const Vec2 v = world.velocity(traced.body);
        // %.9g: the fewest significant digits that always give back the same float.
        std::fprintf(out, "%lld,%s,%.9g,%.9g,%.9g,%.9g\n", static_cast<long long>(step),
                     traced.csvId.c_str(), static_cast<double>(p.x), static_cast<double>(p.y),
                     static_cast<double>(v.x), static_cast<double>(v.y));
    }
}

} // namespace jostle::cli
