# Sourced by the firmware scripts (and `pnpm bench`): checks for the system tools a step needs
# before it runs, so that a missing one fails with the name of the Debian package that provides it
# instead of a CMake or compiler error. scripts/setup.sh installs every one of these packages.
#
#   . "$here/require.sh"
#   require_host_build            # and/or require_arm_build, require_tool, require_header
#   require_end "firmware"        # reports everything missing at once and exits 1, or returns
#
# The compilers checked are the ones the steps use: $CXX (else c++, as CMake picks) for the host
# build, $ARM_CXX (else arm-none-eabi-g++) for the size check. Pointing either at a compiler that
# does not exist, or running with a PATH that lacks a tool, shows the message a fresh machine gets.

require_missing_=''
require_packages_=''

# require_note_ PROBLEM PACKAGE
require_note_() {
  require_missing_="$require_missing_  $1 (Debian package $2)
"
  case " $require_packages_ " in
  *" $2 "*) ;;
  *) require_packages_="$require_packages_ $2" ;;
  esac
}

# require_tool COMMAND PACKAGE
require_tool() {
  command -v "$1" >/dev/null 2>&1 || require_note_ "$1 not found" "$2"
}

# require_header COMPILER HEADER PACKAGE [COMPILER FLAGS...]: the compiler finds the header
# (preprocessing only, so it costs a fraction of a second). A missing compiler is require_tool's.
require_header() {
  require_cxx_=$1 require_header_=$2 require_package_=$3
  shift 3
  command -v "$require_cxx_" >/dev/null 2>&1 || return 0
  printf '#include <%s>\n' "$require_header_" |
    "$require_cxx_" "$@" -x c++ -E -o /dev/null - >/dev/null 2>&1 ||
    require_note_ "$require_cxx_ cannot find <$require_header_>" "$require_package_"
}

# require_library COMPILER FILE PACKAGE [COMPILER FLAGS...]: the compiler's library search path
# has the file (gcc prints the bare name back when it does not).
require_library() {
  require_cxx_=$1 require_file_=$2 require_package_=$3
  shift 3
  command -v "$require_cxx_" >/dev/null 2>&1 || return 0
  case $("$require_cxx_" "$@" -print-file-name="$require_file_" 2>/dev/null) in
  */*) ;;
  *) require_note_ "$require_cxx_ cannot find $require_file_" "$require_package_" ;;
  esac
}

# What firmware/CMakeLists.txt and its tests need: CMake (with ctest), Ninja, the host C++
# compiler, and the GoogleTest, nlohmann-json and mbedTLS headers.
require_host_build() {
  require_tool cmake cmake
  require_tool ctest cmake
  require_tool ninja ninja-build
  require_tool "${CXX:-c++}" g++
  require_header "${CXX:-c++}" gtest/gtest.h libgtest-dev
  require_header "${CXX:-c++}" nlohmann/json.hpp nlohmann-json3-dev
  require_header "${CXX:-c++}" mbedtls/md.h libmbedtls-dev
}

# What size-check.sh needs: the arm-none-eabi compiler and binutils, its C++ standard headers,
# and newlib (nano) to link the image.
require_arm_build() {
  require_tool "${ARM_CXX:-arm-none-eabi-g++}" gcc-arm-none-eabi
  require_tool arm-none-eabi-size gcc-arm-none-eabi
  require_header "${ARM_CXX:-arm-none-eabi-g++}" cstddef libstdc++-arm-none-eabi-newlib \
    -mcpu=cortex-m4 -mthumb -std=c++17
  require_library "${ARM_CXX:-arm-none-eabi-g++}" libc_nano.a libnewlib-arm-none-eabi \
    -mcpu=cortex-m4 -mthumb -mfloat-abi=soft
}

# require_end WHO: if anything was missing, says what and how to install it, and exits 1.
require_end() {
  [ -z "$require_missing_" ] && return 0
  printf '%s: missing system packages:\n%s' "$1" "$require_missing_" >&2
  printf 'install them with: sudo apt-get install -y%s\n' "$require_packages_" >&2
  printf '(bash scripts/setup.sh installs everything the project needs)\n' >&2
  exit 1
}
