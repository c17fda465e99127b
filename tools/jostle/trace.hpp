// The CSV trace of `jostle run --trace`: one row per moving body after a step.
//
//     step,id,x,y,vx,vy
//     1,crate,0.666666687,0.222222239,40,13.333334
//
// Floats are printed with %.9g, enough digits to read back the very same float, so a
// trace can be compared bit for bit with another run or another program.
#pragma once

#include "jostle/world.hpp"

#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

namespace jostle::cli {

/// A body a trace follows, with its id already in CSV form.
struct TracedBody {
    BodyId body;
    std::string csvId;
};

/// `text` as one CSV field (RFC 4180): quoted only when it holds a comma, a quote or a
/// line break, so that ordinary ids stay as they are.
std::string csvField(const std::string& text);

void writeTraceHeader(std::FILE* out);

/// One row per body, in the order given.
void writeTraceRows(std::FILE* out, std::int64_t step, const World& world,
                    std::span<const TracedBody> bodies);

} // namespace jostle::cli
