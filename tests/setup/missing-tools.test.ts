// What a machine without one of the system packages sees: every step that needs a tool fails
// with the Debian package to install, before any compiler or CMake error. The missing tool is
// simulated (a PATH without it, or a compiler that cannot see the headers), never uninstalled.
import { chmodSync, existsSync, mkdtempSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, describe, expect, it } from 'vitest';
import { benchmarksUsingEmulator, ensureEmulator } from '../../bench/ensure-emulator.js';
import { requireChromium } from '../e2e/chromium.js';
import { runProcess } from '../helpers/run-process.js';
import { pathWithout } from './fake-path.js';
import type { FakePath } from './fake-path.js';
import { whichCommand } from './probe.js';

const root = fileURLToPath(new URL('../..', import.meta.url));
const work = mkdtempSync(join(tmpdir(), 'missing-tools-'));
const fakes: FakePath[] = [];
afterAll(() => {
  for (const fake of fakes) fake.remove();
  rmSync(work, { recursive: true, force: true });
});

function without(...commands: string[]): string {
  const fake = pathWithout(commands);
  fakes.push(fake);
  return fake.path;
}

/** A compiler that runs the real one with extra flags (e.g. hiding the standard headers). */
function compilerShim(name: string, real: string, ...flags: string[]): string {
  const path = join(work, name);
  const realPath = whichCommand(real);
  if (realPath === undefined) throw new Error(`${real} is not installed (bash scripts/setup.sh)`);
  writeFileSync(path, `#!/bin/sh\nexec "${realPath}" ${flags.join(' ')} "$@"\n`);
  chmodSync(path, 0o755);
  return path;
}

async function runScript(script: string, env: NodeJS.ProcessEnv, cwd = root) {
  const run = await runProcess('/bin/sh', [join(root, script)], {
    cwd,
    env: { ...process.env, ...env },
    timeoutMs: 120_000,
  });
  return { status: run.status, output: `${run.stdout}${run.stderr}` };
}

describe('firmware/scripts/test.sh on a machine without a package', () => {
  it('names cmake and ninja-build when they are missing, before configuring anything', async () => {
    const build = join(work, 'build-no-cmake');
    const run = await runScript('firmware/scripts/test.sh', {
      PATH: without('cmake', 'ninja'),
      CUBE_BUILD_DIR: build,
    });
    expect(run.status).toBe(1);
    expect(run.output).toContain('cmake not found (Debian package cmake)');
    expect(run.output).toContain('ninja not found (Debian package ninja-build)');
    expect(run.output).toContain('sudo apt-get install -y cmake ninja-build');
    expect(existsSync(build)).toBe(false);
  });

  it('names libgtest-dev, nlohmann-json3-dev and libmbedtls-dev when the compiler cannot find their headers', async () => {
    const build = join(work, 'build-no-headers');
    const run = await runScript('firmware/scripts/test.sh', {
      CXX: compilerShim('c++-no-headers', 'c++', '-nostdinc', '-nostdinc++'),
      CUBE_BUILD_DIR: build,
    });
    expect(run.status).toBe(1);
    expect(run.output).toContain(
      'sudo apt-get install -y libgtest-dev nlohmann-json3-dev libmbedtls-dev',
    );
    expect(run.output).not.toMatch(/fatal error|CMake Error/);
    expect(existsSync(build)).toBe(false);
  });

  it('names g++ when there is no host C++ compiler', async () => {
    const run = await runScript('firmware/scripts/test.sh', {
      CXX: join(work, 'no-such-compiler'),
      CUBE_BUILD_DIR: join(work, 'build-no-cxx'),
    });
    expect(run.status).toBe(1);
    expect(run.output).toContain('no-such-compiler not found (Debian package g++)');
  });

  it('names gcc-arm-none-eabi up front when the arm toolchain for the size check is missing', async () => {
    const build = join(work, 'build-no-arm');
    const run = await runScript('firmware/scripts/test.sh', {
      PATH: without('arm-none-eabi-g++', 'arm-none-eabi-size'),
      CUBE_BUILD_DIR: build,
    });
    expect(run.status).toBe(1);
    expect(run.output).toContain('arm-none-eabi-g++ not found (Debian package gcc-arm-none-eabi)');
    expect(existsSync(build)).toBe(false);
  });
});

describe('firmware/scripts/size-check.sh on a machine without a package', () => {
  it('names libstdc++-arm-none-eabi-newlib, not a compiler error, when the arm C++ headers are missing', async () => {
    const run = await runScript('firmware/scripts/size-check.sh', {
      ARM_CXX: compilerShim('arm-g++-no-libstdcxx', 'arm-none-eabi-g++', '-nostdinc++'),
    });
    expect(run.status).toBe(1);
    expect(run.output).toContain(
      'cannot find <cstddef> (Debian package libstdc++-arm-none-eabi-newlib)',
    );
    expect(run.output).not.toContain('fatal error');
  });

  it('names gcc-arm-none-eabi when the arm compiler is missing', async () => {
    const run = await runScript('firmware/scripts/size-check.sh', {
      PATH: without('arm-none-eabi-g++', 'arm-none-eabi-size'),
    });
    expect(run.status).toBe(1);
    expect(run.output).toContain('sudo apt-get install -y gcc-arm-none-eabi');
  });

  it('is a ctest test that fails with the package name when the arm compiler is missing', async () => {
    // Configured and run without arm-none-eabi-g++ on PATH: the test is still registered, and fails.
    const build = join(work, 'build-ctest');
    const env = { ...process.env, PATH: without('arm-none-eabi-g++', 'arm-none-eabi-size') };
    const configure = await runProcess(
      'cmake',
      ['-S', join(root, 'firmware'), '-B', build, '-G', 'Ninja'],
      { env, timeoutMs: 120_000 },
    );
    expect(configure.status, `${configure.stdout}${configure.stderr}`).toBe(0);
    const ctest = await runProcess(
      'ctest',
      ['--test-dir', build, '-R', '^SizeCheck\\.', '--output-on-failure'],
      { env, timeoutMs: 120_000 },
    );
    const output = `${ctest.stdout}${ctest.stderr}`;
    expect(ctest.status).not.toBe(0);
    expect(output).toMatch(/SizeCheck\.CoreBuildsForA32BitTarget \.+\*\*\*Failed/);
    expect(output).toContain('arm-none-eabi-g++ not found (Debian package gcc-arm-none-eabi)');
  });
});

describe('pnpm bench, which builds cube-emulator itself', () => {
  it('builds the emulator only for the benchmarks that start it', () => {
    const dir = join(root, 'bench');
    expect(benchmarksUsingEmulator(dir, ['physical.bench.ts', 'astar.bench.ts'])).toEqual([
      'physical.bench.ts',
    ]);
  });

  it('builds a missing emulator, and leaves an up-to-date one as it is', async () => {
    const build = join(work, 'bench-fresh');
    // the build (a cmake configure and a ninja build) in a process of its own: ensureEmulator
    // waits for them synchronously, as a benchmark may, and a test may not for that long
    const helper = new URL('../../bench/ensure-emulator.ts', import.meta.url).href;
    const script = `const { ensureEmulator } = await import(${JSON.stringify(helper)});
console.log(ensureEmulator({ buildDir: ${JSON.stringify(build)} }));`;
    const built = await runProcess(
      process.execPath,
      ['--conditions=@hal/source', '--import', 'tsx', '--input-type=module', '-e', script],
      { cwd: root, timeoutMs: 280_000 },
    );
    expect(built.status, built.stderr).toBe(0);
    const path = built.stdout.trim();
    expect(path).toBe(join(build, 'cube-emulator'));
    const builtAt = statSync(path).mtimeMs;
    const help = await runProcess(path, ['--help'], { timeoutMs: 10_000 });
    expect(`${help.stdout}${help.stderr}`).toContain('--udp-port');
    expect(ensureEmulator({ buildDir: build })).toBe(path);
    expect(statSync(path).mtimeMs).toBe(builtAt);
  }, 300_000);

  it('names cmake when it cannot build the emulator, and touches no build directory', () => {
    const build = join(work, 'bench-build');
    expect(() =>
      ensureEmulator({ buildDir: build, env: { ...process.env, PATH: without('cmake') } }),
    ).toThrow(/cmake not found \(Debian package cmake\)/);
    expect(existsSync(build)).toBe(false);
  });
});

describe('the browser tests on a machine without Chromium', () => {
  it('name the Debian package chromium', () => {
    expect(() => requireChromium({ CHROMIUM_PATH: join(work, 'no-chromium') })).toThrow(
      /install the Debian package chromium/,
    );
  });
});
