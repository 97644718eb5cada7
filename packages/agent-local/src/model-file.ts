import { open, stat } from 'node:fs/promises';
import { homedir } from 'node:os';
import { join, resolve } from 'node:path';
import { LocalModelError } from './errors.js';

/**
 * The default model, which `hal model pull` (`pullDefaultModel`) puts in the cache:
 * SmolLM2-135M-Instruct, Q4_1 (Apache-2.0).
 */
export const DEFAULT_MODEL_NAME = 'SmolLM2-135M-Instruct.Q4_1.gguf';

/**
 * Where `hal model pull` puts the default model: `$XDG_CACHE_HOME/hal/models/` (`~/.cache/hal/models/` when
 * XDG_CACHE_HOME is unset).
 */
export function defaultModelFile(
  env: Readonly<Record<string, string | undefined>> = process.env,
): string {
  const cache = env['XDG_CACHE_HOME'];
  const base = cache !== undefined && cache !== '' ? cache : join(homedir(), '.cache');
  return join(base, 'hal', 'models', DEFAULT_MODEL_NAME);
}

/**
 * Whether `path` names the default model's file ({@link defaultModelFile}), however it is
 * written (relative, with `..`). A caller runs it as it runs the default: with few tools and the
 * short prompt the small model needs.
 */
export function isDefaultModelFile(
  path: string,
  env: Readonly<Record<string, string | undefined>> = process.env,
): boolean {
  return resolve(path) === resolve(defaultModelFile(env));
}

const GGUF_MAGIC = 'GGUF';

/**
 * Checks at once that `path` is a GGUF file, before llama.cpp spends seconds on it: it must exist,
 * be a file, and start with the GGUF magic. Throws a LocalModelError MODEL_MISSING (naming the
 * command that fetches it when it is the default model) or MODEL_INVALID.
 */
export async function checkModelFile(path: string, isDefault: boolean): Promise<void> {
  const fix = isDefault
    ? ': run `hal model pull` to fetch it (`npx hal model pull` in an app, `pnpm hal model pull` in a checkout), or give another GGUF file'
    : '';
  let size: number;
  try {
    const info = await stat(path);
    if (!info.isFile())
      throw new LocalModelError('MODEL_INVALID', `model file ${path} is not a file`);
    size = info.size;
  } catch (cause) {
    if (cause instanceof LocalModelError) throw cause;
    throw new LocalModelError('MODEL_MISSING', `model file ${path} not found${fix}`, {
      details: { path },
      cause,
    });
  }
  const handle = await open(path, 'r');
  try {
    const head = Buffer.alloc(4);
    const { bytesRead } = await handle.read(head, 0, 4, 0);
    const magic = head.subarray(0, bytesRead).toString('latin1');
    if (magic !== GGUF_MAGIC) {
      throw new LocalModelError(
        'MODEL_INVALID',
        `model file ${path} is not a GGUF model (it starts with ${JSON.stringify(magic)}, not "GGUF"; ${size} bytes)${fix}`,
        { details: { path, size } },
      );
    }
  } finally {
    await handle.close();
  }
}
