// Finds a declared system tool on this machine, and asks dpkg which package owns a file.
import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync, realpathSync } from 'node:fs';
import { join } from 'node:path';
import type { SystemTool } from './system-tools.js';

function output(command: string, args: readonly string[], input?: string): string | undefined {
  const run = spawnSync(command, args, { encoding: 'utf8', input, timeout: 30_000 });
  return run.status === 0 ? run.stdout : undefined;
}

/** The command's file, symlinks resolved, or undefined when it is not on PATH. */
export function whichCommand(name: string): string | undefined {
  const found = output('sh', ['-c', 'command -v "$1"', 'sh', name])?.trim();
  return found === undefined || found === '' ? undefined : realpathSync(found);
}

function cmakeConfigDirs(): string[] {
  const roots = ['/usr/lib/cmake', '/usr/share/cmake', '/usr/local/lib/cmake'];
  const multiarch = existsSync('/usr/lib')
    ? readdirSync('/usr/lib').map((d) => join('/usr/lib', d, 'cmake'))
    : [];
  return [...roots, ...multiarch].filter((dir) => existsSync(dir));
}

/** Where the tool is on this machine, or undefined when it is missing. */
export function locate(tool: SystemTool): string | undefined {
  const compiler = tool.compiler ?? 'c++';
  const flags = tool.flags ?? [];
  switch (tool.kind) {
    case 'command':
      return whichCommand(tool.name);
    case 'header': {
      // -M lists the files the include pulled in; the header is the one ending in its name.
      const deps = output(
        compiler,
        [...flags, '-x', 'c++', '-M', '-'],
        `#include <${tool.name}>\n`,
      );
      const file = deps
        ?.split(/[\s\\]+/)
        .find((word) => word.endsWith(`/${tool.name}`) && word.startsWith('/'));
      return file === undefined ? undefined : realpathSync(file);
    }
    case 'library': {
      const file = output(compiler, [...flags, `-print-file-name=${tool.name}`])?.trim();
      return file !== undefined && file.includes('/') && existsSync(file)
        ? realpathSync(file)
        : undefined;
    }
    case 'cmake-package': {
      const configs = [`${tool.name}Config.cmake`, `${tool.name.toLowerCase()}-config.cmake`];
      for (const dir of cmakeConfigDirs()) {
        for (const entry of readdirSync(dir).filter((d) => d.startsWith(tool.name))) {
          const config = configs.map((c) => join(dir, entry, c)).find((c) => existsSync(c));
          if (config !== undefined) return config;
        }
      }
      return undefined;
    }
  }
}

export const hasDpkg = whichCommand('dpkg') !== undefined;

/** The package that installed the file (under merged /usr, dpkg may know it as /bin/...). */
export function dpkgOwner(file: string): string | undefined {
  const candidates = [file, file.replace(/^\/usr\/(bin|sbin|lib)\//, '/$1/')];
  for (const candidate of candidates) {
    const line = output('dpkg', ['-S', candidate])?.split('\n')[0];
    // "libgtest-dev:amd64: /usr/include/gtest/gtest.h"
    const owner = line?.slice(0, line.lastIndexOf(': ')).split(',')[0]?.trim();
    if (owner !== undefined && owner !== '') return owner.replace(/:.*$/, '');
  }
  return undefined;
}

/** The packages a package depends on directly (names only, alternatives included). */
export function dpkgDepends(pkg: string): string[] {
  const depends = output('dpkg-query', ['-W', '-f', '${Depends}', pkg]) ?? '';
  return depends
    .split(/[,|]/)
    .map((d) =>
      d
        .trim()
        .replace(/\s*\(.*\)$/, '')
        .replace(/:.*$/, ''),
    )
    .filter((d) => d !== '');
}

export function dpkgEssential(pkg: string): boolean {
  return output('dpkg-query', ['-W', '-f', '${Essential}', pkg])?.trim() === 'yes';
}
