// Keeps the README's commands working on a fresh Debian machine: scripts/setup.sh must install
// the package of every system tool the build, the tests and the benchmarks use. The tools are
// declared in system-tools.ts; what the project's files actually use is read from them, so a new
// find_package(), compiler or script command without a declared package fails here.
import { readdirSync, readFileSync } from 'node:fs';
import { basename, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { DEFAULT_CHROMIUM_PATH } from '../e2e/chromium.js';
import {
  aptPackages,
  cmakeUses,
  readmeTestCommand,
  requireChecks,
  shellCommands,
} from './discover.js';
import type { UsedTool } from './discover.js';
import { dpkgDepends, dpkgEssential, dpkgOwner, hasDpkg, locate, whichCommand } from './probe.js';
import { BASE_CMAKE_PACKAGES, BASE_COMMANDS, SYSTEM_TOOLS } from './system-tools.js';
import type { SystemTool } from './system-tools.js';

const root = fileURLToPath(new URL('../..', import.meta.url));
const read = (path: string) => readFileSync(join(root, path), 'utf8');
const scriptsDir = 'firmware/scripts';
const firmwareScripts = () =>
  readdirSync(join(root, scriptsDir))
    .filter((name) => name.endsWith('.sh'))
    .map((name) => ({ source: `${scriptsDir}/${name}`, text: read(`${scriptsDir}/${name}`) }));

const covers = (tool: SystemTool, used: { kind: string; name: string; compiler?: string }) =>
  tool.kind === used.kind &&
  tool.name === used.name &&
  (tool.kind === 'command' || cxxOf(tool) === cxxOf(used));
const cxxOf = (t: { compiler?: string }) => t.compiler ?? 'c++';

/** What the project uses that neither system-tools.ts nor the base system accounts for. */
function undeclared(used: readonly UsedTool[]): string[] {
  return used
    .filter((u) => !(u.kind === 'command' && BASE_COMMANDS.includes(u.name)))
    .filter((u) => !(u.kind === 'cmake-package' && BASE_CMAKE_PACKAGES.includes(u.name)))
    .filter((u) => !SYSTEM_TOOLS.some((tool) => covers(tool, u)))
    .map((u) => `${u.kind} ${u.name} (${u.source})`);
}

function usedByProject(): UsedTool[] {
  return [
    ...cmakeUses(read('firmware/CMakeLists.txt'), 'firmware/CMakeLists.txt'),
    ...shellCommands(firmwareScripts()),
    { kind: 'command', name: basename(DEFAULT_CHROMIUM_PATH), source: 'tests/e2e/chromium.ts' },
  ];
}

describe('scripts/setup.sh', () => {
  const installed = aptPackages(read('scripts/setup.sh'));

  it('installs the package of every declared system tool', () => {
    const missing = SYSTEM_TOOLS.filter((tool) => !installed.includes(tool.package)).map(
      (tool) => `${tool.package} (for ${tool.kind} ${tool.name}: ${tool.why})`,
    );
    expect(missing).toEqual([]);
  });

  it('installs no package that no declared tool needs', () => {
    const unexplained = installed.filter((pkg) => !SYSTEM_TOOLS.some((t) => t.package === pkg));
    expect(unexplained).toEqual([]);
  });
});

describe('the declared system tools (tests/setup/system-tools.ts)', () => {
  it('include everything firmware/CMakeLists.txt looks for and compiles with', () => {
    const used = cmakeUses(read('firmware/CMakeLists.txt'), 'firmware/CMakeLists.txt');
    expect(used.map((u) => u.name)).toEqual(expect.arrayContaining(['GTest', 'c++']));
    expect(undeclared(used)).toEqual([]);
  });

  it('include every command the firmware scripts run', () => {
    const used = shellCommands(firmwareScripts());
    expect(used.map((u) => u.name)).toEqual(
      expect.arrayContaining(['cmake', 'ctest', 'arm-none-eabi-g++', 'arm-none-eabi-size']),
    );
    expect(undeclared(used)).toEqual([]);
  });

  it('include the browser the end-to-end tests launch', () => {
    expect(undeclared(usedByProject().filter((u) => u.source === 'tests/e2e/chromium.ts'))).toEqual(
      [],
    );
  });

  it('name the same package as each check of firmware/scripts/require.sh', () => {
    const checks = requireChecks(read(`${scriptsDir}/require.sh`));
    expect(checks.length).toBeGreaterThanOrEqual(10);
    const mismatched = checks
      .filter((check) => !SYSTEM_TOOLS.some((t) => covers(t, check) && t.package === check.package))
      .map((check) => `${check.kind} ${check.name} -> ${check.package}`);
    expect(mismatched).toEqual([]);
  });

  it('would report a new find_package, find_program, compiler or script command that is not declared', () => {
    const cmake = cmakeUses(
      [
        'project(x C CXX)',
        'find_package(Boost REQUIRED)',
        'find_program(PROTOC NAMES protoc)',
        'find_path(ZLIB_DIR zlib.h)',
        'find_library(SSL ssl)',
        'set(CMAKE_CXX_COMPILER clang++-19)',
      ].join('\n'),
      'example',
    );
    const shell = shellCommands([
      {
        source: 'example.sh',
        text: 'set -eu\nTOOL=${MY_TOOL:-gcovr}\n"$TOOL" -r . | lcov --list\n',
      },
    ]);
    expect(undeclared([...cmake, ...shell])).toEqual([
      'cmake-package Boost (example)',
      'command protoc (example)',
      'header zlib.h (example)',
      'library libssl.so (example)',
      'command cc (example)',
      'command clang++-19 (example)',
      'command gcovr (example.sh)',
      'command lcov (example.sh)',
    ]);
  });

  it(
    hasDpkg
      ? 'are all on this machine, each from its declared package or a direct dependency of it (dpkg -S)'
      : 'are all on this machine (dpkg is not here: which package provides each is not checked)',
    () => {
      const problems: string[] = [];
      for (const tool of SYSTEM_TOOLS) {
        const file = locate(tool);
        if (file === undefined) {
          problems.push(`${tool.kind} ${tool.name}: not found (install ${tool.package})`);
          continue;
        }
        if (!hasDpkg) continue;
        const owner = dpkgOwner(file);
        if (owner !== tool.package && !dpkgDepends(tool.package).includes(owner ?? '')) {
          problems.push(`${tool.kind} ${tool.name}: ${file} is from ${owner}, not ${tool.package}`);
        }
      }
      expect(problems).toEqual([]);
    },
  );

  it(
    hasDpkg
      ? 'leave out only base commands that are on this machine, from Essential packages'
      : 'leave out only base commands that are on this machine (dpkg is not here: Essential is not checked)',
    () => {
      const base = [
        ...new Set(
          usedByProject()
            .filter((u) => BASE_COMMANDS.includes(u.name))
            .map((u) => u.name),
        ),
      ];
      expect(base.length).toBeGreaterThan(0);
      const problems = base.flatMap((name) => {
        const file = whichCommand(name);
        if (file === undefined) return [`${name}: not found`];
        const owner = hasDpkg ? dpkgOwner(file) : undefined;
        return hasDpkg && (owner === undefined || !dpkgEssential(owner))
          ? [`${name}: ${file} is from ${owner}, not an Essential package`]
          : [];
      });
      expect(problems).toEqual([]);
    },
  );
});

describe('.ci/run', () => {
  it("runs exactly the README's test command, after only environment settings", () => {
    const command = readmeTestCommand(read('README.md'));
    expect(command).toBe('bash scripts/setup.sh && pnpm test');
    const lines = read('.ci/run')
      .split('\n')
      .map((line) => line.trim())
      .filter((line) => line !== '' && !line.startsWith('#'));
    expect(lines.at(-1)).toBe(command);
    expect(lines.slice(0, -1).filter((line) => !/^(set|cd|export) /.test(line))).toEqual([]);
  });
});
