#!/usr/bin/env bash
# The installed zeroset, as a user meets it: `cmake --install` into a fresh
# prefix, then a program built against it with find_package(zeroset) and
# with pkg-config, the installed program run, and the installed Python
# module imported from the prefix. Usage: run.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" > "$work/install.log"
test -f "$prefix/include/zeroset/zeroset.hpp"

cmake -S "$source/tests/consumer" -B "$work/cmake" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" > "$work/configure.log"
cmake --build "$work/cmake" > "$work/build.log"
"$work/cmake/consumer" "$work/cmake.exr"

pc_dir=$(dirname "$(find "$prefix" -name zeroset.pc)")
flags=$(PKG_CONFIG_PATH=$pc_dir pkg-config --cflags --libs --static zeroset)
# shellcheck disable=SC2086  # the flags are words
c++ -std=c++20 -O1 "$source/tests/consumer/main.cpp" -o "$work/consumer-pc" $flags
"$work/consumer-pc" "$work/pkg-config.exr"

"$prefix/bin/zeroset" --version
"$prefix/bin/zeroset" render -q --width 16 --height 12 -o "$work/program.png"

module_dir=$(dirname "$(find "$prefix" -name 'zeroset.cpython-*.so' | head -n 1)")
if [ "$module_dir" != . ]; then
  PYTHONPATH=$module_dir /usr/bin/python3 -c "
import zeroset, sys
assert zeroset.__file__.startswith('$prefix'), zeroset.__file__
print('python: imported', zeroset.__file__, zeroset.render(zeroset.default_scene(), 8, 6).shape)"
fi
echo "consumer: the installed zeroset works"
