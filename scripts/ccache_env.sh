# Sourced by the scripts that build: where ccache compiles (CMakeLists.txt, EOMGEN_CCACHE), paths under the
# checkout are hashed relative to it, so that a fresh clone elsewhere on the same machine (CI's) finds what an
# earlier build compiled. Nothing happens without ccache. The base is the checkout's root wherever this is sourced
# from (sourced in build/, $PWD would key the entries relative to build/, and no other clone would find them).
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}"
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
