# shellcheck shell=bash
# shellcheck disable=SC2034,SC2154 # $demo comes from, and $failed goes back to, the script
# Shared by the demo's test scripts (sourced, not run): runs jostle-demo with --report
# and checks the values it prints, and counts the pixels of a colour in its screenshots.
# Needs $demo set (and $checker, check_screenshot, for count and pixels); sets $failed to
# 1 on a failure.
failed=0
report=""
# offscreen: runs the demo on SDL's offscreen video driver (no X server) from here on;
# exits the script with 77 (the tests' SKIP_RETURN_CODE) if SDL cannot open a window so.
offscreen() {
  export SDL_VIDEODRIVER=offscreen
  if ! "$demo" --frames 1 >/dev/null 2>&1; then
    echo "skipped: jostle-demo cannot open a window with SDL_VIDEODRIVER=offscreen"
    exit 77
  fi
}
# run ARGS...: runs the demo with --report, keeps its report in $report.
run() {
  if ! report=$("$demo" --report "$@"); then
    echo "FAIL: jostle-demo $* exited with an error" >&2
    failed=1
    report=""
  fi
}
value() { printf '%s\n' "$report" | awk -v k="$1" '$1 == k { print $2 }'; }
# expect NAME VALUE WHY: the reported NAME is VALUE exactly.
expect() {
  local got
  got=$(value "$1")
  if [ "$got" != "$2" ]; then
    echo "FAIL: $3: $1 is '$got', expected '$2'" >&2
    failed=1
  else
    echo "ok: $3 ($1 $got)"
  fi
}
# near NAME VALUE TOLERANCE WHY: the reported NAME is within TOLERANCE of VALUE.
near() {
  local got
  got=$(value "$1")
  if ! awk -v g="$got" -v e="$2" -v t="$3" \
      'BEGIN { exit !(g != "" && g - e <= t && e - g <= t) }'; then
    echo "FAIL: $4: $1 is '$got', expected $2 +- $3" >&2
    failed=1
  else
    echo "ok: $4 ($1 $got)"
  fi
}
# below NAME LIMIT WHY: the reported NAME is less than LIMIT.
below() {
  local got
  got=$(value "$1")
  if ! awk -v g="$got" -v l="$2" 'BEGIN { exit !(g != "" && g < l) }'; then
    echo "FAIL: $3: $1 is '$got', expected below $2" >&2
    failed=1
  else
    echo "ok: $3 ($1 $got)"
  fi
}
# count FILE COLOUR X0 Y0 X1 Y1: the pixels of that colour in the rectangle.
count() { "$checker" "$1" --count "$2" "$3" "$4" "$5" "$6" || echo "error"; }
# pixels WHY FILE COLOUR X0 Y0 X1 Y1 EXPECTED: exactly EXPECTED pixels of that colour.
pixels() {
  local why=$1 got
  shift
  got=$(count "$1" "$2" "$3" "$4" "$5" "$6")
  if [ "$got" != "$7" ]; then
    echo "FAIL: $why: $got pixels of $2 in ($3, $4)-($5, $6), expected $7" >&2
    failed=1
  else
    echo "ok: $why ($got pixels)"
  fi
}
