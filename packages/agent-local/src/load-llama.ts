// node-llama-cpp is an optional peer dependency of this package: a program that never runs a local
// model (the simulator and the tools, `hal --help`, a hosted model) neither installs its hundreds
// of megabytes of prebuilt llama.cpp builds nor loads them. It is imported here, when a model is
// first loaded, and its absence is a LocalModelError that says what to install.
import type * as NodeLlamaCppModule from 'node-llama-cpp';
import { errorMessage } from '@hal/types';
import { LocalModelError } from './errors.js';

/** node-llama-cpp's module, as `import('node-llama-cpp')` gives it. */
export type NodeLlamaCpp = typeof NodeLlamaCppModule;

/** What to run to add it, in the message of the DEPENDENCY_MISSING error. */
export const INSTALL_NODE_LLAMA_CPP = 'npm install node-llama-cpp';

/** Whether `error` says that the package `name` itself is not installed (not one it imports). */
function isMissingPackage(error: unknown, name: string): boolean {
  if (!(error instanceof Error)) return false;
  const code = (error as NodeJS.ErrnoException).code;
  return (
    (code === 'ERR_MODULE_NOT_FOUND' || code === 'MODULE_NOT_FOUND') &&
    error.message.includes(`'${name}'`)
  );
}

/**
 * node-llama-cpp, imported on first use. Rejects with a LocalModelError: DEPENDENCY_MISSING when
 * it is not installed (naming {@link INSTALL_NODE_LLAMA_CPP}), CONFIG when it is there but does
 * not load (its own error is the cause). `load` is for tests.
 */
export async function loadNodeLlamaCpp(
  load: () => Promise<NodeLlamaCpp> = () => import('node-llama-cpp'),
): Promise<NodeLlamaCpp> {
  try {
    return await load();
  } catch (cause) {
    if (isMissingPackage(cause, 'node-llama-cpp')) {
      throw new LocalModelError(
        'DEPENDENCY_MISSING',
        `the local model runs on node-llama-cpp, an optional peer dependency of @hal/agent-local that is not installed: ${INSTALL_NODE_LLAMA_CPP}`,
        { details: { package: 'node-llama-cpp', install: INSTALL_NODE_LLAMA_CPP }, cause },
      );
    }
    throw new LocalModelError(
      'CONFIG',
      `node-llama-cpp is installed but could not be loaded: ${errorMessage(cause)}`,
      { cause },
    );
  }
}
