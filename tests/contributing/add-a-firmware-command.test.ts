// CONTRIBUTING.md, "Add a firmware command", checked: a command is a row in many places (the C++
// core's command list and dispatch, its handler, its GoogleTest, the protocol doc, the
// TypeScript reply schema and request parameters, the mock robot), and this test reads every one
// of those places for every command the firmware knows, so a command added to one and not the
// others fails here, naming the place. It also holds the recipe's build and test commands to
// docs/firmware.md's, and the GoogleTest suite the recipe filters on to the test source.
import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { REPLY_SCHEMAS } from '@hal/physical/protocol';
import { commandLines, shellBlocks } from '../docs/shell-blocks.js';

const root = new URL('../../', import.meta.url);
const read = (path: string): string => readFileSync(new URL(path, root), 'utf8');
const core = 'firmware/esp32-s3-stepper/src/core/';

/** The commands the firmware accepts: `Cube::IsCommand`'s list in cube_request.cpp. */
function firmwareCommands(): string[] {
  const source = read(`${core}cube_request.cpp`);
  const list = /kCommands\[\]\s*=\s*\{([^}]*)\}/.exec(source)?.[1];
  if (list === undefined) throw new Error(`${core}cube_request.cpp: no kCommands list`);
  return [...list.matchAll(/"([a-z_]+)"/g)].map((m) => m[1]!);
}

const commands = firmwareCommands();
/** The handler a command dispatches to: `if (Equals(cmd, "set_led")) return CmdSetLed(r);`. */
const dispatched = new Map(
  [
    ...read(`${core}cube_request.cpp`).matchAll(/Equals\(cmd, "([a-z_]+)"\)\) return (Cmd\w+)\(/g),
  ].map((m) => [m[1]!, m[2]!]),
);
const firmwareTests = readdirSync(new URL('firmware/tests/', root))
  .filter((f) => f.endsWith('_test.cpp'))
  .map((f) => read(`firmware/tests/${f}`))
  .join('\n');

describe('every firmware command is in each place the recipe names', () => {
  it('the firmware knows the commands (the list is read at all)', () => {
    expect(commands).toEqual(expect.arrayContaining(['hello', 'move_cm', 'set_led', 'estop']));
  });

  it.each(commands)('%s', (command) => {
    const handler = dispatched.get(command);
    expect(handler, `cube_request.cpp's Dispatch sends "${command}" to a handler`).toBeDefined();
    expect(read(`${core}cube.h`), `cube.h declares ${handler}`).toContain(
      `void ${handler}(Reply& r);`,
    );
    const defined = ['cube_commands.cpp', 'cube_motion_commands.cpp'].some((f) =>
      read(`${core}${f}`).includes(`void Cube::${handler}(Reply& r)`),
    );
    expect(defined, `${handler} is defined in cube_commands.cpp or cube_motion_commands.cpp`).toBe(
      true,
    );
    expect(firmwareTests, `a GoogleTest in firmware/tests sends "${command}"`).toMatch(
      new RegExp(`\\{"cmd", "${command}"\\}|\\\\"cmd\\\\":\\s*\\\\"${command}\\\\"`),
    );
    expect(read('docs/protocol.md'), `docs/protocol.md has a section for ${command}`).toMatch(
      new RegExp(`^### 5\\.\\d+ \`${command}\``, 'm'),
    );
    expect(
      Object.keys(REPLY_SCHEMAS),
      `REPLY_SCHEMAS (packages/physical/src/protocol/schemas.ts) has ${command}`,
    ).toContain(command);
    expect(
      read('packages/physical/src/protocol/schemas.ts'),
      `RequestParams has ${command}`,
    ).toMatch(new RegExp(`^  ${command}: `, 'm'));
    // every command is a case of the mock's handlers, but the hello that opens a session
    const mock =
      read('packages/physical/src/mock/command-handlers.ts').includes(`case '${command}':`) ||
      read('packages/physical/src/mock/mock-robot.ts').includes(`envelope.cmd === '${command}'`);
    expect(mock, `the mock robot (command-handlers.ts) handles ${command}`).toBe(true);
  });

  it('and the TypeScript side knows no command the firmware lacks', () => {
    expect(Object.keys(REPLY_SCHEMAS).sort()).toEqual([...commands].sort());
  });
});

describe("the recipe's commands", () => {
  const contributing = shellBlocks(read('CONTRIBUTING.md'), 'CONTRIBUTING.md').blocks;
  const recipe = contributing.filter((b) => b.text.includes('ctest'));
  const firmwareDoc = shellBlocks(read('docs/firmware.md'), 'docs/firmware.md').blocks.flatMap(
    (b) => commandLines(b),
  );

  it("build and test the firmware with docs/firmware.md's own commands", () => {
    expect(recipe, 'a CONTRIBUTING.md block runs ctest').toHaveLength(1);
    const lines = commandLines(recipe[0]!);
    const builds = lines.filter((l) => /^(cmake|bash firmware\/scripts)/.test(l));
    expect(builds.length).toBeGreaterThan(0);
    for (const line of builds) expect(firmwareDoc, line).toContain(line);
  });

  it('filter on a GoogleTest suite that exists', () => {
    const filters = [...recipe[0]!.text.matchAll(/ctest .*-R '?([A-Za-z]+)\\?\.'?/g)].map(
      (m) => m[1]!,
    );
    expect(filters.length).toBeGreaterThan(0);
    for (const suite of filters) expect(firmwareTests).toContain(`TEST(${suite}, `);
  });
});
