// CONTRIBUTING.md, "Add a robot setting", checked: the recipe is the one written at the head of
// packages/types/src/robot-settings.ts, every file and name it cites is where it says, the tests
// it says will name what is missing exist, its regenerate command is the one settings-vectors.ts
// documents, and a row of ROBOT_SETTINGS is all the host needs (the schema, the V1 defaults and
// the vectors follow from it).
import { existsSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { RobotConfigSchema, ROBOT_SETTINGS, V1_ROBOT } from '@hal/types';
import { commandLines, shellBlocks } from '../docs/shell-blocks.js';
import { buildSettingsVectors } from '../vectors/settings-vectors.js';

const root = new URL('../../', import.meta.url);
const read = (path: string): string => readFileSync(new URL(path, root), 'utf8');
const core = 'firmware/esp32-s3-stepper/src/core/';

/** `[file, a name the recipe says is in it]`, in the order of the recipe. */
const CITED: readonly (readonly [string, string])[] = [
  ['packages/types/src/robot-settings.ts', 'export const ROBOT_SETTINGS'],
  [`${core}settings.h`, 'kSettings'],
  [`${core}cube.h`, 'struct CubeConfig {'],
  [`${core}cube_commands.cpp`, 'void Cube::CmdSetConfig(Reply& r)'],
  [`${core}cube_commands.cpp`, 'void WriteConfigFields(JsonWriter& w, const CubeConfig& c)'],
  ['firmware/tests/vectors_test.cpp', 'double BootValue(const std::string& wire)'],
  ['tests/vectors/settings-table.test.ts', 'const cppNames: Record<string, string> = {'],
  ['packages/physical/src/protocol/schemas.ts', 'export const DeviceConfigSchema = z.object({'],
  ['docs/protocol.md', '### 5.10 `set_config`'],
  ['tests/vectors/settings-vectors.ts', 'export function buildSettingsVectors'],
];

/** The tests that name what a half-added setting is missing (settings-table.test.ts). */
const DRIFT_TESTS = [
  'is what tests/vectors/settings.json holds',
  'settings.h has the set_config rows, in order, with the same ranges and units',
  'boots with the defaults of the table (cube.h, kinematics.h)',
  'protocol.md section 5.10 has one row per set_config field: type, range, default',
];

describe('adding a robot setting (CONTRIBUTING.md: Add a robot setting)', () => {
  const header = read('packages/types/src/robot-settings.ts').split('*/')[0] ?? '';
  const contributing = read('CONTRIBUTING.md');

  it('follows the recipe written in robot-settings.ts, which names every place below', () => {
    expect(header).toContain('To add a setting');
    for (const name of [
      'settings.h',
      'CubeConfig',
      'CmdSetConfig',
      'WriteConfigFields',
      'BootValue',
      'DeviceConfigSchema',
      'section 5.10',
      'settings-vectors.ts',
    ]) {
      expect(header, `robot-settings.ts' recipe names ${name}`).toContain(name);
    }
  });

  it.each(CITED)('%s has %s', (file, name) => {
    expect(existsSync(new URL(file, root)), `${file} exists`).toBe(true);
    expect(read(file)).toContain(name);
    expect(contributing, `CONTRIBUTING.md cites ${file}`).toContain(file);
  });

  it('names the drift tests that exist in settings-table.test.ts', () => {
    const tests = read('tests/vectors/settings-table.test.ts');
    for (const title of DRIFT_TESTS) expect(tests, title).toContain(title);
  });

  it("regenerates the vectors with settings-vectors.ts' own command", () => {
    const documented = /`(node [^`]*settings-vectors\.ts)`/.exec(
      read('tests/vectors/settings-vectors.ts'),
    )?.[1];
    expect(documented).toBeDefined();
    const lines = shellBlocks(contributing, 'CONTRIBUTING.md').blocks.flatMap((b) =>
      commandLines(b),
    );
    expect(lines).toContain(documented);
  });

  it('gets the host schema, the V1 defaults and the vectors from the rows of the table', () => {
    const keys = ROBOT_SETTINGS.map((row) => row.key);
    expect(Object.keys(RobotConfigSchema.shape)).toEqual(keys);
    const vectors = JSON.parse(JSON.stringify(buildSettingsVectors())) as {
      settings: { key: string; default: number }[];
    };
    for (const row of ROBOT_SETTINGS) {
      expect(V1_ROBOT[row.key as keyof typeof V1_ROBOT], row.key).toBe(row.default);
      expect(
        vectors.settings.find((s) => s.key === row.key)?.default,
        `settings.json's ${row.key}`,
      ).toBe(row.default);
    }
  });
});
