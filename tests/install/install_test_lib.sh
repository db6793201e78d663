# install_test_lib.sh - what the install tests (tests/install/*_test.sh)
# share: failing with a message, and timing each step for the log.
fail() { echo "FAIL: $*" >&2; exit 1; }
seconds() { date +%s.%N; }
# the seconds since $1 (a `seconds` reading), to a tenth
elapsed() { awk -v a="$1" -v b="$(seconds)" 'BEGIN { printf "%.1f", b - a }'; }
test_start=$(seconds)
