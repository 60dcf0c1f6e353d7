#!/bin/sh
# One version number everywhere: the project's (project(ede VERSION ...) in CMakeLists.txt, given here by
# CMake) must be what every built tool's --version prints, what a new log's header records, what the
# CMake package and ede.pc declare, what the Python module reports (where it is built), what CITATION.cff
# cites, and a heading of CHANGELOG.md, under its "Unreleased" section.
#
# Usage: test_version_everywhere.sh SOURCE_DIR BUILD_DIR VERSION
set -eu
src=$1 build=$2 version=$3
fail() { echo "test_version_everywhere: FAILED: $*" >&2; exit 1; }
work=$build/tests/version-everywhere
rm -rf "$work"
mkdir -p "$work"

tools=0
for tool in ede-sim ede-replay ede-stats ede-crater ede-render ede-sweep ede-bench ede-bench-elastic ede-view; do
  [ -x "$build/tools/$tool" ] || continue
  tools=$((tools + 1))
  got=$("$build/tools/$tool" --version)
  [ "$got" = "$tool, ede $version" ] || fail "$tool --version prints '$got', not '$tool, ede $version'"
done
[ "$tools" -ge 8 ] || fail "only $tools tools built"

# A log's header: ede-replay info's "engine" line names the version that wrote it and its trajectory
# revision ("0.1.0+t1", libede/src/core/engine_revision.hpp).
printf 'seed = 1\n[[species]]\nname = "a"\ncount = 2\nradius = 0.1\n[species.placement]\nkind = "explicit"\npositions = [[0.3, 0.5], [0.7, 0.5]]\n[species.velocity]\nkind = "list"\nvalues = [[1.0, 0.0], [-1.0, 0.0]]\n[stop]\ntime = 1\n' \
  >"$work/two.toml"
"$build/tools/ede-sim" "$work/two.toml" -q -o "$work/two.ede" >/dev/null
"$build/tools/ede-replay" info "$work/two.ede" | grep -q "^engine *ede $version+t[0-9][0-9]*," ||
  fail "the log header does not record ede $version: $("$build/tools/ede-replay" info "$work/two.ede" | grep engine)"

grep -q "^Version: $version\$" "$build/ede.pc" || fail "ede.pc: $(grep ^Version "$build/ede.pc")"
grep -q "set(PACKAGE_VERSION \"$version\")" "$build/edeConfigVersion.cmake" || fail "edeConfigVersion.cmake names another version"

if [ -d "$build/python/ede" ] && [ -x /usr/bin/python3 ]; then
  got=$(PYTHONPATH="$build/python" PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 -c 'import ede; print(ede.__version__)') ||
    fail "the Python module does not import"
  [ "$got" = "$version" ] || fail "ede.__version__ is '$got'"
fi

grep -q "^version: $version\$" "$src/CITATION.cff" || fail "CITATION.cff: $(grep '^version' "$src/CITATION.cff")"
first=$(grep -m1 '^## ' "$src/CHANGELOG.md")
[ "$first" = "## Unreleased" ] || fail "CHANGELOG.md opens with '$first', not '## Unreleased'"
grep -q "^## $version\\b" "$src/CHANGELOG.md" || fail "CHANGELOG.md has no section for $version"
echo "test_version_everywhere: $version in $tools tools, the log header, ede.pc, the CMake package, CITATION.cff, CHANGELOG.md"
