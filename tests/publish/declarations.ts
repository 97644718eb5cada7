// A user's TypeScript file that imports every entry of the installed packages, compiled by the
// app's own tsc with skipLibCheck off: every declaration file it reaches is checked, the packages'
// and their dependencies' alike.
import { execFile } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { cleanEnv } from './temp-app.js';

const run = promisify(execFile);

/**
 * The tsconfig.json of a strict user project: Node's module resolution and types, TypeScript's
 * default `lib` (which has the DOM's types), nothing skipped.
 */
export const USER_TSCONFIG = {
  compilerOptions: {
    strict: true,
    target: 'es2022',
    module: 'nodenext',
    moduleResolution: 'nodenext',
    types: ['node'],
    skipLibCheck: false,
    noEmit: true,
  },
  files: ['check-types.ts'],
};

/** Writes a file importing each of `specifiers` and compiles it; resolves with tsc's output. */
export async function compileImports(
  appDir: string,
  specifiers: readonly string[],
): Promise<{ ok: boolean; output: string }> {
  writeFileSync(join(appDir, 'tsconfig.json'), `${JSON.stringify(USER_TSCONFIG, null, 2)}\n`);
  writeFileSync(
    join(appDir, 'check-types.ts'),
    [
      ...specifiers.map((specifier, i) => `import * as m${i} from '${specifier}';`),
      `export const entries = [${specifiers.map((_, i) => `m${i}`).join(', ')}];`,
      '',
    ].join('\n'),
  );
  try {
    const { stdout, stderr } = await run(
      process.execPath,
      [join(appDir, 'node_modules', 'typescript', 'bin', 'tsc'), '-p', 'tsconfig.json'],
      { cwd: appDir, env: cleanEnv(), timeout: 270_000, maxBuffer: 16 * 1024 * 1024 },
    );
    return { ok: true, output: stdout + stderr };
  } catch (error) {
    const failed = error as { stdout?: string; stderr?: string; message: string };
    return { ok: false, output: `${failed.stdout ?? ''}${failed.stderr ?? ''}` || failed.message };
  }
}
