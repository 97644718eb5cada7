// Reads, from the project's own files, what they need from the system: the packages
// scripts/setup.sh installs, the tools firmware/CMakeLists.txt looks for, the commands the
// firmware scripts run, the checks they declare, and the README's test command. Plain text
// scanning, deliberately small: it has to see what a new line in those files would add.
import type { ToolKind } from './system-tools.js';

/** A tool as the build or a script uses it (compiler: the one that must find a header/library). */
export interface UsedTool {
  kind: ToolKind;
  name: string;
  compiler?: string;
  /** Where it was found, for the failure message. */
  source: string;
}

/** The words of the `apt_packages=( ... )` array in scripts/setup.sh, comments left out. */
export function aptPackages(setupScript: string): string[] {
  const body = /^apt_packages=\(([\s\S]*?)^\)/m.exec(setupScript)?.[1];
  if (body === undefined) throw new Error('scripts/setup.sh has no apt_packages=( ... ) list');
  return body
    .split('\n')
    .map((line) => line.replace(/#.*$/, ''))
    .flatMap((line) => line.split(/\s+/))
    .filter((word) => word !== '');
}

const LANGUAGE_COMPILERS: Record<string, string> = { CXX: 'c++', C: 'cc' };

/** What a CMakeLists.txt asks of the system: find_* calls, languages and compilers it sets. */
export function cmakeUses(text: string, source: string): UsedTool[] {
  const code = text.replace(/#.*$/gm, '');
  const used: UsedTool[] = [];
  const add = (kind: ToolKind, name: string, compiler?: string) =>
    used.push(compiler === undefined ? { kind, name, source } : { kind, name, compiler, source });
  const args = (call: string) =>
    [...code.matchAll(new RegExp(`\\b${call}\\s*\\(([^)]*)\\)`, 'gi'))].map((m) =>
      (m[1] ?? '').trim().split(/\s+/),
    );
  // The first name after the result variable (or after NAMES).
  const firstName = (words: string[]) => {
    const names = words.indexOf('NAMES');
    return names >= 0 ? words[names + 1] : words[1];
  };
  for (const words of args('find_package')) if (words[0]) add('cmake-package', words[0]);
  for (const words of args('find_program')) {
    const name = firstName(words);
    if (name !== undefined) add('command', name);
  }
  for (const words of args('find_path')) {
    const name = firstName(words);
    if (name !== undefined) add('header', name, 'c++');
  }
  for (const words of args('find_library')) {
    const name = firstName(words);
    if (name !== undefined) add('library', `lib${name}.so`, 'c++');
  }
  for (const words of args('project')) {
    const rest = words.slice(1);
    const languages = rest.filter((w) => w in LANGUAGE_COMPILERS);
    // project(name) with no language list enables C and CXX.
    const bare = languages.length === 0 && !rest.includes('NONE') && !rest.includes('LANGUAGES');
    for (const language of bare ? ['C', 'CXX'] : languages) {
      add('command', LANGUAGE_COMPILERS[language] as string);
    }
  }
  for (const words of args('enable_language')) {
    for (const language of words.filter((w) => w in LANGUAGE_COMPILERS)) {
      add('command', LANGUAGE_COMPILERS[language] as string);
    }
  }
  for (const m of code.matchAll(/CMAKE_(?:C|CXX)_COMPILER[\s=]+"?([\w.+/-]+)/g)) {
    if (m[1] !== undefined && !m[1].startsWith('$')) add('command', m[1].replace(/^.*\//, ''));
  }
  return used;
}

// Words that precede a command (skipped), and built-ins (which run no external command).
const SHELL_KEYWORDS = new Set('if then else elif fi do done while until time'.split(' '));
const SHELL_BUILTINS = new Set(
  (
    'return exit set shift trap export local readonly unset cd pwd command . source eval exec ' +
    'wait read printf echo test [ true false : type hash umask esac'
  ).split(' '),
);

/** Splits shell text into simple commands, respecting quotes and $( ) nesting. */
function shellSegments(text: string): string[] {
  const segments: string[] = [];
  // One buffer per open command substitution; quote state per level.
  const stack: { buf: string; quote: '' | "'" | '"' }[] = [{ buf: '', quote: '' }];
  const top = () => stack[stack.length - 1] as { buf: string; quote: '' | "'" | '"' };
  const cut = () => {
    segments.push(top().buf);
    top().buf = '';
  };
  for (let i = 0; i < text.length; i += 1) {
    const c = text[i] as string;
    const level = top();
    if (level.quote === "'") {
      if (c === "'") level.quote = '';
      level.buf += c;
    } else if (c === '$' && text[i + 1] === '(') {
      level.buf += '$SUB';
      stack.push({ buf: '', quote: '' });
      i += 1;
    } else if (level.quote === '"') {
      if (c === '"') level.quote = '';
      level.buf += c;
    } else if (c === "'" || c === '"') {
      level.quote = c;
      level.buf += c;
    } else if (c === ')' && stack.length > 1) {
      cut();
      stack.pop();
    } else if (c === '&' && /[<>]$/.test(level.buf)) {
      level.buf += c; // 2>&1
    } else if (';|&(){}!\n'.includes(c)) {
      cut();
    } else {
      level.buf += c;
    }
  }
  while (stack.length > 0) {
    segments.push(top().buf);
    stack.pop();
  }
  return segments;
}

/** `NAME=value` assignments, with `${OTHER:-default}` read as its default. */
function shellAssignments(text: string): Map<string, string> {
  const values = new Map<string, string>();
  for (const m of text.matchAll(/(?:^|\s)([A-Za-z_]\w*)=("?)(\$\{\w+:-([^}]*)\}|[^\s$"]+)\2/g)) {
    const [, name, , whole, fallback] = m;
    if (name !== undefined && whole !== undefined) values.set(name, fallback ?? whole);
  }
  return values;
}

/** Removes here-document bodies (`<<'EOF'` ... `EOF`), which are data, not commands. */
function withoutHeredocs(text: string): string {
  return text.replace(/<<-?\s*['"]?(\w+)['"]?([^\n]*)\n[\s\S]*?\n\1\n/g, '$2\n');
}

/**
 * Removes what looks like a command but is not one: arithmetic `$(( ))`, and the patterns of
 * `case` branches (`stepper-*)`, `a | b)`), which start a line inside `case ... esac`.
 */
function withoutNonCommands(text: string): string {
  return text
    .replace(/\$\(\([^()]*\)\)/g, '$ARITH')
    .replace(/\bcase\b[\s\S]*?\besac\b/g, (block) => block.replace(/^(\s*)[^\n()]*?\)/gm, '$1'));
}

/**
 * The external commands shell scripts run (functions they define and shell built-ins left out);
 * a command held in a variable counts as the variable's default (`CXX=${ARM_CXX:-arm-none-eabi-g++}`).
 */
export function shellCommands(scripts: { text: string; source: string }[]): UsedTool[] {
  const texts = scripts.map((s) => ({
    source: s.source,
    text: withoutNonCommands(withoutHeredocs(s.text.replace(/(^|\s)#.*$/gm, '$1'))),
  }));
  const functions = new Set(
    texts.flatMap((s) => [...s.text.matchAll(/^\s*([A-Za-z_]\w*)\s*\(\)/gm)].map((m) => m[1])),
  );
  const used: UsedTool[] = [];
  for (const { text, source } of texts) {
    const assignments = shellAssignments(text);
    for (const segment of shellSegments(text)) {
      // leading assignments first, whole (a quoted value may hold spaces)
      const words = segment
        .trim()
        .replace(/^(?:[A-Za-z_]\w*=(?:"[^"]*"|'[^']*'|\S*)\s*)+/, '')
        .split(/\s+/);
      let word = words.find((w) => !/^[A-Za-z_]\w*=/.test(w) && !SHELL_KEYWORDS.has(w));
      if (word === undefined || word === '' || word.startsWith('$SUB')) continue;
      if (word === 'for' || word === 'case' || SHELL_BUILTINS.has(word)) continue;
      const variable = /^"?\$\{?(\w+)\}?"?$/.exec(word)?.[1];
      if (variable !== undefined) {
        word = assignments.get(variable);
        if (word === undefined || word.startsWith('$')) continue; // a parameter: not knowable here
      }
      word = word.replace(/^["']|["']$/g, '');
      if (!/^[A-Za-z_][\w.+-]*$/.test(word) || functions.has(word) || SHELL_BUILTINS.has(word))
        continue;
      used.push({ kind: 'command', name: word, source });
    }
  }
  return used;
}

/** A check a script declares with require.sh: `require_tool NAME PKG`, `require_header CXX NAME PKG`. */
export interface DeclaredCheck {
  kind: 'command' | 'header' | 'library';
  name: string;
  compiler?: string;
  package: string;
}

export function requireChecks(text: string): DeclaredCheck[] {
  const value = (word: string) => {
    const unquoted = word.replace(/^"|"$/g, '');
    return /^\$\{\w+:-(.*)\}$/.exec(unquoted)?.[1] ?? unquoted;
  };
  const checks: DeclaredCheck[] = [];
  for (const m of text.matchAll(
    /^[ \t]*require_(tool|header|library)[ \t]+(\S+)[ \t]+(\S+)(?:[ \t]+(\S+))?/gm,
  )) {
    const [, kind, a, b, c] = m;
    if (a === undefined || b === undefined) continue;
    if (kind === 'tool') checks.push({ kind: 'command', name: value(a), package: b });
    else if (c !== undefined)
      checks.push({
        kind: kind === 'header' ? 'header' : 'library',
        compiler: value(a),
        name: b,
        package: c,
      });
  }
  return checks;
}

/** The shell command in the README's fenced block that runs `pnpm test`. */
export function readmeTestCommand(readme: string): string {
  const blocks = [...readme.matchAll(/```sh\n([\s\S]*?)```/g)].map((m) => (m[1] ?? '').trim());
  const command = blocks.find((block) => /(^|\s)pnpm test$/.test(block));
  if (command === undefined) throw new Error('README.md has no ```sh block ending in "pnpm test"');
  return command;
}
