#!/bin/sh
# The manual pages as a user gets them: `cmake --install` into a temporary prefix, then for every tool in
# bin/: its page in share/man/man1 and one per subcommand its --help lists; each page renders with man
# without a warning, names the version the tool prints, and holds every long option of the tool's (or the
# subcommand's) --help, so a page made from an older --help fails. Skips (77) where the build made no pages
# (no help2man, or a sanitizer build).
#
# Usage: test_man_pages.sh BUILD_DIR WORK_DIR PAGES_BUILT(ON|OFF)
set -eu
build=$1 work=$2 built=$3
fail() { echo "test_man_pages: FAILED: $*" >&2; exit 1; }
[ "$built" = ON ] || { echo "test_man_pages: this build makes no manual pages (see CMake's message)"; exit 77; }
command -v man >/dev/null || { echo "test_man_pages: man is not installed"; exit 77; }

rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >"$work/install.log" || fail "cmake --install (see $work/install.log)"
man1=$prefix/share/man/man1

# check_page PAGE COMMAND...: PAGE.1 renders cleanly and holds every long option COMMAND --help lists.
check_page() {
  page=$1
  shift
  [ -f "$man1/$page.1" ] || fail "$page.1 is not installed in share/man/man1"
  LC_ALL=C MANWIDTH=250 man --nh --nj --warnings -l "$man1/$page.1" >"$work/$page.txt" 2>"$work/$page.warnings" ||
    fail "man could not render $page.1"
  [ ! -s "$work/$page.warnings" ] || { cat "$work/$page.warnings"; fail "man warns about $page.1"; }
  "$@" --help >"$work/$page.help"
  for option in $(grep -oE -- '--[a-z0-9][a-z0-9-]*' "$work/$page.help" | sort -u); do
    grep -q -F -- "$option" "$work/$page.txt" || fail "$page.1 lacks $option, which '$* --help' lists"
  done
}

tools=0
for exe in "$prefix"/bin/ede-*; do
  tool=$(basename "$exe")
  tools=$((tools + 1))
  check_page "$tool" "$exe"
  version=$("$exe" --version | sed -n 's/^[^,]*, ede //p')
  grep -q "ede $version" "$work/$tool.txt" || fail "$tool.1 does not name version $version"
  # The SEE ALSO list may wrap after a hyphen inside a page's name (ede-stats has twelve): join such lines.
  sed -e ':a' -e '/-$/{N;s/-\n *\([a-z]\)/-\1/;ta' -e '}' "$work/$tool.txt" >"$work/$tool.joined"
  for sub in $(sed -n '/^Subcommands:/,$p' "$work/$tool.help" | sed -n 's/^  \([a-z0-9-]*\) .*/\1/p'); do
    check_page "$tool-$sub" "$exe" "$sub"
    grep -q "$tool-$sub(1)" "$work/$tool.joined" || fail "$tool.1 does not point to $tool-$sub(1)"
  done
done
[ "$tools" -ge 8 ] || fail "only $tools tools installed"
echo "test_man_pages: passed ($tools tools, $(ls "$man1" | wc -l) pages)"
