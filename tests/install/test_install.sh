#!/bin/sh
# The installed library, as a user gets it: `cmake --install` into a temporary prefix, then
#  - the layout: public headers only (no internal header), libede.a, the CMake package, ede.pc, the tools,
#    the plotting scripts;
#  - examples/hello configured with find_package(ede) and CMAKE_PREFIX_PATH, built, run on a scene: the
#    state it prints from its log must be the very numbers the installed ede-replay prints;
#  - a one-line program compiled and linked with nothing but `pkg-config --cflags --libs --static ede`;
#  - the installed ede-stats run from another folder plots with the installed scripts.
# The public headers compile with no internal header because the prefix holds none.
#
# Usage: test_install.sh SOURCE_DIR BUILD_DIR WORK_DIR LIBDIR C_COMPILER CXX_COMPILER [EXTRA_FLAGS]
# EXTRA_FLAGS: compile and link flags the library was built with that a program must repeat (sanitizers).
set -eu
src=$1 build=$2 work=$3 libdir=$4 cc=$5 cxx=$6 flags=${7:-}
fail() { echo "test_install: FAILED: $*" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >"$work/install.log" || fail "cmake --install (see $work/install.log)"

for f in include/ede/ede.hpp "$libdir/libede.a" "$libdir/cmake/ede/edeConfig.cmake" \
         "$libdir/cmake/ede/edeConfigVersion.cmake" "$libdir/cmake/ede/edeTargets.cmake" \
         "$libdir/pkgconfig/ede.pc" bin/ede-sim bin/ede-replay bin/ede-stats bin/ede-crater bin/ede-render bin/ede-sweep \
         bin/ede-bench bin/ede-bench-elastic share/ede/plot/ede_style.py share/ede/plot/plot_hist.py; do
  [ -e "$prefix/$f" ] || fail "$f is not installed"
done
public=$(cd "$src/libede/include/ede" && ls *.hpp | sort | tr '\n' ' ')
installed=$(cd "$prefix/include/ede" && ls | sort | tr '\n' ' ')
[ "$public" = "$installed" ] || fail "include/ede holds '$installed', not the public headers '$public'"
[ "$(ls "$prefix/include")" = "ede" ] || fail "include/ holds more than ede/"

# examples/hello through find_package(ede).
cmake -S "$src/examples/hello" -B "$work/hello-build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="$flags" >"$work/hello-configure.log" 2>&1 ||
  { cat "$work/hello-configure.log"; fail "configuring examples/hello against the installed package"; }
cmake --build "$work/hello-build" >"$work/hello-build.log" 2>&1 ||
  { cat "$work/hello-build.log"; fail "building examples/hello against the installed package"; }
"$work/hello-build/hello" "$src/examples/scenes/mixture.toml" "$work/mixture.ede" 0.25 >"$work/hello.out" ||
  fail "hello did not run"
cat "$work/hello.out"
grep -q "^ran .*mixture.toml: reached stop.time$" "$work/hello.out" || fail "hello did not report its run"
grep -q "^log: [0-9]* events; at t = 0.25, after [0-9]* of them, 1250 disks$" "$work/hello.out" ||
  fail "hello did not report the log"
# The state of disk 0 at t = 0.25, as the installed ede-replay writes it: id,species,x,y,vx,vy,...
row=$("$prefix/bin/ede-replay" state "$work/mixture.ede" --at 0.25 | sed -n 2p)
expected=$(echo "$row" | awk -F, '{ printf "disk 0: x %s y %s vx %s vy %s", $3, $4, $5, $6 }')
got=$(grep "^disk 0:" "$work/hello.out")
[ "$got" = "$expected" ] || fail "hello printed '$got', ede-replay gives '$expected'"

# A one-line program through pkg-config alone.
printf '#include <ede/ede.hpp>\nint main(int, char** argv) { return ede::load_scene_file(argv[1]).ok() ? 0 : 1; }\n' \
  >"$work/one.cpp"
pc_flags=$(PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig" pkg-config --cflags --libs --static ede) ||
  fail "pkg-config does not know the installed ede.pc"
# shellcheck disable=SC2086  # the flags are words
"$cxx" -std=c++20 $flags "$work/one.cpp" -o "$work/one" $pc_flags || fail "compiling with pkg-config's flags: $pc_flags"
"$work/one" "$src/examples/gas.toml" || fail "the pkg-config program did not load examples/gas.toml"

# The installed ede-stats, run from another folder, plots with the installed scripts: a line added to the
# installed plot_hist.py leaves a mark.
mkdir -p "$work/elsewhere"
printf 'import os\nopen(os.environ["EDE_TEST_PLOT_MARK"], "w").write("installed")\n' >"$work/mark.py"
cat "$work/mark.py" "$prefix/share/ede/plot/plot_hist.py" >"$work/plot_hist.py"
mv "$work/plot_hist.py" "$prefix/share/ede/plot/plot_hist.py"
(cd "$work/elsewhere" && EDE_TEST_PLOT_MARK="$work/mark.txt" "$prefix/bin/ede-stats" hist "$work/mixture.ede" \
  --plot speeds.png >"$work/plot.log" 2>&1) || { cat "$work/plot.log"; fail "installed ede-stats --plot"; }
[ -s "$work/elsewhere/speeds.png" ] || fail "installed ede-stats --plot wrote no figure"
[ "$(cat "$work/mark.txt" 2>/dev/null)" = "installed" ] || fail "installed ede-stats did not run the installed script"
# The installed Python package (where the module was built), imported from another folder by Debian's
# python3 with only the prefix's site-packages added, reads the log the installed tools wrote.
site=$(cd "$prefix" && ls -d lib/python3*/dist-packages 2>/dev/null | head -n 1)
if [ -n "$site" ] && [ -x /usr/bin/python3 ]; then
  x_py=$(cd "$work/elsewhere" && PYTHONPATH="$prefix/$site" /usr/bin/python3 -c \
    'import sys, ede; print(repr(float(ede.open(sys.argv[1]).state(0.25).x[0])))' "$work/mixture.ede") ||
    fail "the installed Python package does not import or read a log"
  x_cli=$(echo "$row" | awk -F, '{ print $3 }')
  /usr/bin/python3 -c 'import sys; sys.exit(float(sys.argv[1]) != float(sys.argv[2]))' "$x_py" "$x_cli" ||
    fail "installed ede.open(...).state(0.25) gives x = $x_py, ede-replay gives $x_cli"
fi
echo "test_install: passed"
