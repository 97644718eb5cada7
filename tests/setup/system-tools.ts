// The system tools the project uses and the Debian package that provides each: the declared side
// of tests/setup/setup-packages.test.ts, which checks that scripts/setup.sh installs every package
// named here and that everything the build and the scripts use is named here.

/**
 * command: an executable looked up on PATH. header: found by `compiler` (with `flags`).
 * library: a file on `compiler`'s library path (gcc's -print-file-name). cmake-package: a
 * find_package() config shipped by the package.
 */
export type ToolKind = 'command' | 'header' | 'library' | 'cmake-package';

export interface SystemTool {
  kind: ToolKind;
  name: string;
  /** The Debian package scripts/setup.sh installs for it (it may come as that package's dependency). */
  package: string;
  why: string;
  compiler?: string;
  flags?: readonly string[];
}

const ARM_FLAGS = ['-mcpu=cortex-m4', '-mthumb', '-mfloat-abi=soft'] as const;
const FUZZER_ARCH = process.arch === 'arm64' ? 'aarch64' : 'x86_64';

export const SYSTEM_TOOLS: readonly SystemTool[] = [
  { kind: 'command', name: 'cmake', package: 'cmake', why: 'configures the firmware host build' },
  { kind: 'command', name: 'ctest', package: 'cmake', why: 'runs the firmware GoogleTest suites' },
  { kind: 'command', name: 'ninja', package: 'ninja-build', why: 'the generator test.sh selects' },
  { kind: 'command', name: 'c++', package: 'g++', why: 'the host C++ compiler CMake picks' },
  {
    kind: 'header',
    name: 'gtest/gtest.h',
    compiler: 'c++',
    package: 'libgtest-dev',
    why: 'the firmware unit tests',
  },
  { kind: 'cmake-package', name: 'GTest', package: 'libgtest-dev', why: 'find_package(GTest)' },
  {
    kind: 'header',
    name: 'nlohmann/json.hpp',
    compiler: 'c++',
    package: 'nlohmann-json3-dev',
    why: 'the firmware tests read the JSON golden vectors',
  },
  {
    kind: 'cmake-package',
    name: 'nlohmann_json',
    package: 'nlohmann-json3-dev',
    why: 'find_package(nlohmann_json)',
  },
  {
    kind: 'header',
    name: 'mbedtls/md.h',
    compiler: 'c++',
    package: 'libmbedtls-dev',
    why: 'HMAC-SHA256 of the host build (find_path)',
  },
  {
    kind: 'library',
    name: 'libmbedcrypto.so',
    compiler: 'c++',
    package: 'libmbedtls-dev',
    why: 'HMAC-SHA256 of the host build (find_library mbedcrypto)',
  },
  {
    kind: 'command',
    name: 'arm-none-eabi-g++',
    package: 'gcc-arm-none-eabi',
    why: 'size-check.sh compiles the core for a 32-bit target',
  },
  {
    kind: 'command',
    name: 'arm-none-eabi-size',
    package: 'gcc-arm-none-eabi',
    why: 'size-check.sh prints code and RAM size (binutils-arm-none-eabi, a dependency)',
  },
  {
    kind: 'header',
    name: 'cstddef',
    compiler: 'arm-none-eabi-g++',
    flags: ARM_FLAGS,
    package: 'libstdc++-arm-none-eabi-newlib',
    why: 'the C++ standard headers of the arm target (the core includes <cstddef>)',
  },
  {
    kind: 'library',
    name: 'libc_nano.a',
    compiler: 'arm-none-eabi-g++',
    flags: ARM_FLAGS,
    package: 'libnewlib-arm-none-eabi',
    why: 'size-check.sh links its image against newlib-nano',
  },
  {
    kind: 'command',
    name: 'clang++',
    package: 'clang',
    why: 'builds the libFuzzer targets of the firmware parsers',
  },
  {
    kind: 'library',
    name: `libclang_rt.fuzzer-${FUZZER_ARCH}.a`,
    compiler: 'clang++',
    package: 'libclang-rt-14-dev',
    why: "the libFuzzer runtime clang's -fsanitize=fuzzer links",
  },
  {
    kind: 'command',
    name: 'chromium',
    package: 'chromium',
    why: "the browser demo's end-to-end test (tests/e2e/chromium.ts)",
  },
  {
    kind: 'command',
    name: 'socat',
    package: 'socat',
    why: "docs/firmware.md's smoke checks of a cube or the emulator",
  },
  {
    kind: 'command',
    name: 'nats-server',
    package: 'nats-server',
    why: 'the NATS broker the gateway tests and bench/nats.bench.ts start on 127.0.0.1',
  },
  {
    kind: 'command',
    name: 'openssl',
    package: 'openssl',
    why: "the docs' key and token commands (openssl rand), run by tests/docs/doc-commands.test.ts",
  },
];

/**
 * Commands every Debian system has (its Essential packages: coreutils, dash, bash, grep, sed,
 * findutils, diffutils, debianutils), which setup.sh need not install.
 */
export const BASE_COMMANDS: readonly string[] = [
  'sh',
  'bash',
  'cat',
  'cp',
  'mv',
  'rm',
  'mkdir',
  'mktemp',
  'touch',
  'ls',
  'ln',
  'dirname',
  'basename',
  'readlink',
  'env',
  'head',
  'tail',
  'tr',
  'wc',
  'sort',
  'uniq',
  'cut',
  'printf',
  'echo',
  'test',
  'true',
  'false',
  'grep',
  'sed',
  'find',
  'xargs',
  'cmp',
  'diff',
  'id',
];

/**
 * CMake find_package() names the C library provides (glibc, Essential), not a package to install.
 */
export const BASE_CMAKE_PACKAGES: readonly string[] = ['Threads'];

/** The declared package of a command, for messages such as "install chromium". */
export function packageOfCommand(name: string): string {
  const tool = SYSTEM_TOOLS.find((t) => t.kind === 'command' && t.name === name);
  if (tool === undefined)
    throw new Error(`no system tool "${name}" in tests/setup/system-tools.ts`);
  return tool.package;
}
