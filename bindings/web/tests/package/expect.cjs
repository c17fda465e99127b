// What platformer.ts's level must give, whichever way the package was loaded: the events
// on the frames the level's numbers put them, and the very bits of the C++ version
// (platformer.cpp's line of JSON, given). Prints each check; exits non-zero on a failure.
"use strict";

module.exports = function expect(runner, played, native) {
  let failures = 0;
  const check = (ok, what) => {
    console.log(`${ok ? "ok  " : "FAIL"} ${runner}: ${what}`);
    if (!ok) failures++;
  };
  // The hero's right edge starts at 38 and walks 80 / 60 a step; the coin's left edge is at
  // 92: they overlap after step k when 38 + (k + 1) * 4 / 3 > 92, first at k = 40.
  check(played.coinFrame === 40, `the coin is picked up on frame 40 (${played.coinFrame})`);
  // The jump leaves at x >= 150 (frame 89); up 0.45 s to 81 units above the floor, down
  // 29 units to the platform's top in about 0.27 s more: about 43 frames in the air.
  const flight = played.landedOnPlatformFrame - 89;
  check(flight >= 40 && flight <= 46, `it lands on the one-way platform after about 43 frames in the air (${flight})`);
  check(played.onLiftFrame > played.landedOnPlatformFrame, `then it walks onto the lift (frame ${played.onLiftFrame})`);
  // The lift rises at 40 units a second for a second, and carries it exactly.
  check(Math.abs(played.rise - 40) < 1e-3, `the lift carries it 40 units up in a second (${played.rise})`);
  check(played.liftSpeedUnderFeet === -40, `its ground moves at -40 (${played.liftSpeedUnderFeet})`);
  // C++ prints its floats with 9 digits, which give the float back.
  for (const key of Object.keys(native)) {
    const expected = typeof native[key] === "number" ? Math.fround(native[key]) : native[key];
    check(played[key] === expected, `${key} is C++'s (${played[key]}, C++ ${native[key]})`);
  }
  return failures;
};
