// Runs a documentation example as written, so a README or a docs page cannot rot: its
// `import { a, b } from 'pkg';` lines are bound to modules the test hands in, and the names it
// needs from outside (a `log` standing in for console.log, say) are put in its scope.

/** A module's exports by name, e.g. `import * as nats from '@hal/nats'`. */
export type ExampleModules = Readonly<Record<string, Readonly<Record<string, unknown>>>>;

/** The fenced code blocks of language `lang` in a markdown text, in order. */
export function fencedBlocks(markdown: string, lang: string): string[] {
  return [...markdown.matchAll(new RegExp('```' + lang + '\\n([\\s\\S]*?)```', 'g'))].map(
    (m) => m[1] ?? '',
  );
}

const IMPORT_LINE = /^import \{([^}]*)\} from '([^']+)';$/gm;

type AsyncFunctionConstructor = new (
  ...args: string[]
) => (...values: unknown[]) => Promise<unknown>;
const AsyncFunction = Object.getPrototypeOf(async () => undefined)
  .constructor as AsyncFunctionConstructor;

/**
 * Runs `code` with its named imports taken from `modules` and `scope`'s entries as variables.
 * An import of a module not in `modules`, of a name the module does not export, or any other kind
 * of import (default, namespace) throws before it runs.
 */
export async function runDocExample(
  code: string,
  modules: ExampleModules,
  scope: Readonly<Record<string, unknown>> = {},
): Promise<void> {
  const names: string[] = [];
  const values: unknown[] = [];
  const body = code.replace(IMPORT_LINE, (_all, list: string, from: string) => {
    const module = modules[from];
    if (module === undefined) throw new Error(`the example imports ${from}, unknown to this test`);
    for (const name of list
      .split(',')
      .map((n) => n.trim())
      .filter((n) => n !== '')) {
      if (!(name in module))
        throw new Error(`the example imports ${name} from ${from}, which does not export it`);
      names.push(name);
      values.push(module[name]);
    }
    return '';
  });
  const left = /^import .*$/m.exec(body);
  if (left !== null)
    throw new Error(`the example has an import this runner cannot bind: ${left[0]}`);
  await new AsyncFunction(...names, ...Object.keys(scope), body)(
    ...values,
    ...Object.values(scope),
  );
}
