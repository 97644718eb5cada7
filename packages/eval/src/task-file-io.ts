import { EvalError } from './errors.js';

/** Refuses a task or world file: TASK_INVALID naming the file, the field and why. */
export function refuse(file: string, field: string, why: string): never {
  throw new EvalError('TASK_INVALID', `${file}: "${field}" ${why}`, { file, field });
}

/** The JSON of a task or world file's text; TASK_INVALID naming `file` when it is not JSON. */
export function parseJsonText(text: string, file: string): unknown {
  try {
    return JSON.parse(text) as unknown;
  } catch (cause) {
    throw new EvalError('TASK_INVALID', `${file}: not JSON (${(cause as Error).message})`, {
      file,
      cause,
    });
  }
}

/** The text of a task or world file on disk (Node); TASK_INVALID naming it when unreadable. */
export async function readTextFile(path: string): Promise<string> {
  const { readFile } = await import('node:fs/promises');
  try {
    return await readFile(path, 'utf8');
  } catch (cause) {
    throw new EvalError('TASK_INVALID', `${path}: cannot be read (${(cause as Error).message})`, {
      file: path,
      cause,
    });
  }
}
