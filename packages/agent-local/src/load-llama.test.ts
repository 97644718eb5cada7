// node-llama-cpp loaded on demand: here it is installed (a devDependency of the workspace); where
// it is not, the error names what to install. tests/publish/optional-llama.test.ts installs the
// packed packages without it and meets the same error through createLocalChatProvider.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { afterAll, describe, expect, it } from 'vitest';
import { LocalModelError } from './errors.js';
import { INSTALL_NODE_LLAMA_CPP, loadNodeLlamaCpp } from './load-llama.js';
import type { NodeLlamaCpp } from './load-llama.js';

// a module outside the workspace: node-llama-cpp cannot be resolved from there, as in an app
// that did not install it
const outside = mkdtempSync(join(tmpdir(), 'hal-no-llama-'));
afterAll(() => rmSync(outside, { recursive: true, force: true }));

async function importerFrom(dir: string, specifier: string): Promise<() => Promise<NodeLlamaCpp>> {
  const file = join(dir, `import-${specifier.replace(/\W/g, '-')}.mjs`);
  writeFileSync(file, `export default () => import(${JSON.stringify(specifier)});\n`);
  const module = (await import(pathToFileURL(file).href)) as {
    default: () => Promise<NodeLlamaCpp>;
  };
  return module.default;
}

describe('loadNodeLlamaCpp', () => {
  it('imports node-llama-cpp where it is installed', async () => {
    const llama = await loadNodeLlamaCpp();
    expect(typeof llama.getLlama).toBe('function');
  });

  it('is DEPENDENCY_MISSING, naming the install command, where node-llama-cpp is not installed', async () => {
    const error: unknown = await loadNodeLlamaCpp(
      await importerFrom(outside, 'node-llama-cpp'),
    ).catch((e: unknown) => e);
    expect(error).toBeInstanceOf(LocalModelError);
    expect(error).toMatchObject({
      code: 'DEPENDENCY_MISSING',
      message: expect.stringContaining(INSTALL_NODE_LLAMA_CPP),
      details: { package: 'node-llama-cpp' },
      cause: { code: 'ERR_MODULE_NOT_FOUND' },
    });
    expect(INSTALL_NODE_LLAMA_CPP).toBe('npm install node-llama-cpp');
  });

  it('is CONFIG with the cause when node-llama-cpp is there but a module it needs is not', async () => {
    const error: unknown = await loadNodeLlamaCpp(
      await importerFrom(outside, 'some-package-node-llama-cpp-needs'),
    ).catch((e: unknown) => e);
    expect(error).toMatchObject({
      code: 'CONFIG',
      message: expect.stringContaining("'some-package-node-llama-cpp-needs'"),
    });
  });
});
