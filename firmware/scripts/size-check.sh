#!/bin/sh
# Compiles the firmware core for a 32-bit microcontroller target with the
# board's flags (no exceptions, no RTTI, -Os) and the host's strict
# warnings, links it into a minimal image, and prints its code and RAM size.
# Needs Debian's gcc-arm-none-eabi, libstdc++-arm-none-eabi-newlib and libnewlib-arm-none-eabi
# (checked first, by require.sh). ARM_CXX overrides the compiler.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
. "$here/require.sh"
require_arm_build
require_end size-check
core="$here/../esp32-s3-stepper/src/core"
out=${SIZE_CHECK_OUT:-$(mktemp -d)}
trap 'rm -rf "$out"' EXIT
CXX=${ARM_CXX:-arm-none-eabi-g++}
flags="-mcpu=cortex-m4 -mthumb -mfloat-abi=soft -Os -std=c++17 -fno-exceptions -fno-rtti
  -ffunction-sections -fdata-sections -Wall -Wextra -Wconversion -Wsign-conversion -Wshadow -Werror"
objs=""
for src in "$core"/*.cpp; do
  obj="$out/$(basename "$src" .cpp).o"
  # shellcheck disable=SC2086
  $CXX $flags -I"$core" -c "$src" -o "$obj"
  objs="$objs $obj"
done
cat > "$out/image.cpp" <<'CPP'
// A minimal image that keeps every part of the core reachable.
#include "cube.h"
#include "frame.h"
namespace {
struct Clk : cube::Clock { uint64_t t = 0; uint64_t NowUs() override { return t += 100; } };
struct Mot : cube::MotorDriver { void WriteCoils(cube::Wheel, uint8_t) override {} };
struct Rnd : cube::RandomSource { uint32_t NextU32() override { return 4; } };
struct Sink : cube::ByteSink { void Write(const uint8_t*, size_t) override {} };
struct Bridge : cube::LinkHandler {
  cube::Cube* c = nullptr; cube::SerialLink* l = nullptr; uint8_t out[1024];
  void OnMessage(const uint8_t* d, size_t n) override { l->Send(out, c->Handle(d, n, out, sizeof(out)), 0); }
  void OnOversize(size_t n) override { l->Send(out, c->HandleOversize(n, out, sizeof(out)), 0); }
};
Clk clk; Mot mot; Rnd rnd; Sink sink; Bridge bridge;
cube::CubeDeps Deps() { cube::CubeDeps d; d.clock = &clk; d.motors = &mot; d.random = &rnd; return d; }
cube::Cube robot(Deps(), "cube-size");
cube::SerialLink link(sink, bridge, 1);
}
extern "C" volatile uint8_t rx_byte;
volatile uint8_t rx_byte;
int main() {
  bridge.c = &robot; bridge.l = &link;
  for (;;) { uint8_t b = rx_byte; link.Receive(&b, 1, 0); link.Poll(0); robot.Tick(); robot.Poll(); }
}
CPP
# shellcheck disable=SC2086
$CXX $flags -I"$core" -c "$out/image.cpp" -o "$out/image.o"
# shellcheck disable=SC2086
$CXX -mcpu=cortex-m4 -mthumb -mfloat-abi=soft -Os --specs=nano.specs --specs=nosys.specs \
  -Wl,--gc-sections -o "$out/image.elf" "$out/image.o" $objs -lm
echo "core objects (arm-none-eabi, cortex-m4, -Os -fno-exceptions -fno-rtti):"
# shellcheck disable=SC2086
arm-none-eabi-size -t $objs | sed "s|$out/||"
echo "minimal linked image (core + libm + newlib-nano, one Cube and one SerialLink):"
arm-none-eabi-size "$out/image.elf" | sed "s|$out/||"
