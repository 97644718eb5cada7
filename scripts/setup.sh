#!/usr/bin/env bash
# Installs everything this repository needs on a Debian machine with Node.js 20 and npm:
# the system packages (compilers, GoogleTest, Chromium for the browser test, socat),
# pnpm through corepack (pinned by package.json's packageManager), and the workspace packages.
# Safe to run again: it installs only what is missing. tests/setup/ checks that apt_packages
# covers every system tool the build, the tests and the benchmarks use (tests/setup/system-tools.ts).
set -euo pipefail
cd "$(dirname "$0")/.."

log() { printf '[setup] %s\n' "$*" >&2; }

apt_packages=(
  cmake ninja-build g++ # firmware host build (also what pnpm bench builds the emulator with)
  libgtest-dev nlohmann-json3-dev libmbedtls-dev # firmware tests, golden vectors, HMAC
  gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib # 32-bit cross build (size check)
  clang libclang-rt-14-dev # libFuzzer targets for the firmware's parsers (ASan, UBSan)
  chromium # the browser demo's end-to-end test
  socat # serial link tools: the docs' smoke checks and the serial fault-injection test
  nats-server # the NATS broker the gateway tests and the NATS benchmark start on 127.0.0.1
  openssl # the docs' key and token commands (openssl rand), run by the doc-commands test
)

missing=()
for pkg in "${apt_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed' || missing+=("$pkg")
done
if ((${#missing[@]} > 0)); then
  log "installing system packages: ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# pnpm, at the version package.json pins. Corepack's signature check fails against some registry
# mirrors; the version is pinned and the registry's integrity hash is still checked.
export COREPACK_ENABLE_DOWNLOAD_PROMPT=0 COREPACK_INTEGRITY_KEYS=0
if ! command -v pnpm >/dev/null 2>&1; then
  log 'enabling pnpm through corepack'
  if ! corepack enable pnpm; then
    npm install -g --silent corepack
    corepack enable pnpm
  fi
fi
log "pnpm $(pnpm --version)"

pnpm install --frozen-lockfile --reporter=silent
log 'ready'
