// The example of the README, run as written, so it cannot rot.
import { readFileSync } from 'node:fs';
import * as simulation from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import * as fleet from './index.js';

const MODULES: Record<string, Record<string, unknown>> = {
  '@hal/fleet': fleet,
  '@hal/simulation': simulation,
};

const readme = readFileSync(new URL('../README.md', import.meta.url), 'utf8');
const blocks = (lang: string) =>
  [...readme.matchAll(new RegExp('```' + lang + '\\n([\\s\\S]*?)```', 'g'))].map((m) => m[1] ?? '');

async function run(block: string, log: (...values: unknown[]) => void): Promise<void> {
  const names: string[] = [];
  const values: unknown[] = [];
  const body = block.replace(
    /^import \{([^}]*)\} from '([^']+)';$/gm,
    (_all, list: string, from: string) => {
      const module = MODULES[from];
      if (module === undefined)
        throw new Error(`the example imports ${from}, unknown to this test`);
      for (const name of list
        .split(',')
        .map((n) => n.trim())
        .filter((n) => n !== '')) {
        names.push(name);
        values.push(module[name]);
      }
      return '';
    },
  );
  const AsyncFunction = Object.getPrototypeOf(async () => undefined).constructor as new (
    ...args: string[]
  ) => (...values: unknown[]) => Promise<void>;
  await new AsyncFunction(...names, 'console', body)(...values, { log });
}

describe('the README example', () => {
  it('prints what the README says it prints', async () => {
    const [code] = blocks('ts');
    const [expected] = blocks('text');
    const lines: string[] = [];
    await run(code ?? '', (...values) => lines.push(values.map(String).join(' ')));
    expect(`${lines.join('\n')}\n`).toBe(expected);
  }, 60_000);
});
