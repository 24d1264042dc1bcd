#!/usr/bin/env bash
# Regenerates generator/model/reserved_macros.inc: the object-like and function-like macros that the C and
# C++ standard headers, glibc and Eigen define on this platform (g++ -dM -E in C++17, GNU C++17 and C++20),
# as far as they are model-language identifiers. A coordinate or parameter with such a name would be
# rewritten by the preprocessor in the generated header, or in the program that includes it, so the model
# loader refuses it (names.cpp). Names starting with EIGEN_ are refused by a prefix rule instead.
set -euo pipefail
cd "$(dirname "$0")/.."
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
headers=(Eigen/Cholesky Eigen/Core Eigen/LU algorithm array cassert cctype cerrno cfenv cfloat cinttypes climits
         clocale cmath csetjmp csignal cstdarg cstddef cstdint cstdio cstdlib cstring ctime cwchar cwctype
         filesystem fstream functional iomanip iostream iterator limits sstream stdexcept string string_view
         system_error type_traits utility vector)
for h in "${headers[@]}"; do echo "#include <$h>"; done > "$tmp/all.cpp"
for std in c++17 gnu++17 c++20; do
  "${CXX:-g++}" -std="$std" -I/usr/include/eigen3 -dM -E "$tmp/all.cpp"
done | awk '{print $2}' | sed 's/(.*//' | LC_ALL=C sort -u |
  grep -E '^[A-Za-z][A-Za-z0-9_]*$' | grep -v -e '__' -e '_$' -e '^EIGEN_' > "$tmp/names"
{
  echo "// Made by scripts/update_reserved_macros.sh: macros of the standard headers, glibc and Eigen."
  echo "// Sorted (LC_ALL=C) for binary search. Do not edit by hand."
  sed 's/.*/"&",/' "$tmp/names"
} > generator/model/reserved_macros.inc
echo "generator/model/reserved_macros.inc: $(wc -l < "$tmp/names") names"
