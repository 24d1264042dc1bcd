# Sourced by the scripts that build: where ccache compiles (CMakeLists.txt, EOMGEN_CCACHE), paths under the
# checkout are hashed relative to it, so that a fresh clone elsewhere on the same machine (CI's) finds what an
# earlier build compiled. Nothing happens without ccache.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
