// Holds every written copy of the robot's settings to the one table (ROBOT_SETTINGS in
// @hal/types, read through RobotConfigSchema): the committed settings.json, @hal/kinematics'
// FIRMWARE_SETTINGS, the firmware's settings.h and boot defaults, the C++ emulator's flag, and
// the docs' tables and ranges. Any drift fails here, naming the copy.
import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { FIRMWARE_SETTINGS } from '@hal/kinematics';
import { MockRobot } from '@hal/physical/testing';
import { robotConfig, V1_ROBOT } from '@hal/types';
import type { RobotConfig } from '@hal/types';
import { buildSettingsVectors, SETTINGS_VECTORS_PATH, settingsTable } from './settings-vectors.js';
import type { SettingRow } from './settings-vectors.js';

const root = new URL('../../', import.meta.url);
const read = (path: string): string => readFileSync(new URL(path, root), 'utf8');
const core = 'firmware/esp32-s3-stepper/src/core/';

const table = settingsTable();
const setConfigRows = table.filter((r) => r.set_by === 'set_config');
const wireRows = table.filter((r): r is SettingRow & { wire: string } => r.wire !== null);

/** `min..max` as the firmware and the docs write a range. */
const range = (r: SettingRow): string => `${r.min}..${r.max}`;

describe('the settings table', () => {
  it('is what tests/vectors/settings.json holds (regenerate with settings-vectors.ts)', () => {
    const committed: unknown = JSON.parse(readFileSync(SETTINGS_VECTORS_PATH, 'utf8'));
    expect(committed).toEqual(JSON.parse(JSON.stringify(buildSettingsVectors())));
  });

  it('has one row per robot configuration field, with the V1 defaults', () => {
    expect(table.map((r) => r.key).sort()).toEqual(Object.keys(V1_ROBOT).sort());
    for (const r of table) expect(V1_ROBOT[r.key as keyof RobotConfig], r.key).toBe(r.default);
  });

  it('is the range RobotConfigSchema takes: both ends in, just outside refused', () => {
    for (const r of table) {
      const at = (value: number) => () => robotConfig({ [r.key]: value });
      const step = r.integer ? 1 : 0.01;
      if (!r.min_exclusive) expect(at(r.min), `${r.key} at its min`).not.toThrow();
      expect(at(r.max), `${r.key} at its max`).not.toThrow();
      expect(at(r.min_exclusive ? r.min : r.min - step), `${r.key} below`).toThrow();
      expect(at(r.max + step), `${r.key} above`).toThrow();
      if (r.integer) expect(at(r.min + 0.5), `${r.key} a fraction`).toThrow();
    }
  });

  it("is @hal/kinematics' FIRMWARE_SETTINGS (the set_config rows, in the firmware's order)", () => {
    expect(
      FIRMWARE_SETTINGS.map((s) => ({
        key: s.key,
        wire: s.field,
        min: s.min,
        max: s.max,
        integer: s.integer,
        unit: s.unit,
        default: s.default,
        wire_type: s.wireType,
      })),
    ).toEqual(
      setConfigRows.map((r) => ({
        key: r.key,
        wire: r.wire,
        min: r.min,
        max: r.max,
        integer: r.integer,
        unit: r.unit,
        default: r.default,
        wire_type: r.wire_type,
      })),
    );
  });
});

describe("the firmware's C++ and the emulators' flags", () => {
  it('settings.h has the set_config rows, in order, with the same ranges and units', () => {
    const source = read(`${core}settings.h`).replace(/\s+/g, ' ');
    const rows = [
      ...source.matchAll(
        /constexpr Setting k\w+\{ ?"(\w+)", ([\d.]+), ([\d.]+), (true|false), "([^"]+)" ?\};/g,
      ),
    ].map(([, wire, min, max, integer, unit]) => ({
      wire,
      min: Number(min),
      max: Number(max),
      integer: integer === 'true',
      unit,
    }));
    expect(rows).toEqual(
      setConfigRows.map(({ wire, min, max, integer, unit }) => ({ wire, min, max, integer, unit })),
    );
  });

  it('boots with the defaults of the table (cube.h, kinematics.h)', () => {
    const source = read(`${core}cube.h`) + read(`${core}kinematics.h`);
    // The C++ name of each wire field's boot value.
    const cppNames: Record<string, string> = {
      wheel_diameter_cm: 'double wheel_diameter_cm',
      wheel_base_cm: 'double wheel_base_cm',
      steps_per_revolution: 'double steps_per_revolution',
      max_speed_steps_per_s: 'int64_t max_speed_sps',
      acceleration_steps_per_s2: 'int64_t accel_sps2',
      host_timeout_ms: 'int64_t host_timeout_ms',
      max_steps_per_command: 'constexpr int64_t kMaxStepsPerCommand',
    };
    expect(Object.keys(cppNames).sort()).toEqual(wireRows.map((r) => r.wire).sort());
    for (const r of wireRows) {
      const found = new RegExp(`${cppNames[r.wire]} = ([\\d.]+);`).exec(source);
      expect(found?.[1], `the firmware's default of ${r.wire}`).toBeDefined();
      expect(Number(found?.[1]), r.wire).toBe(r.default);
      // a double on the wire is a double in the firmware, an int an int64_t
      expect(cppNames[r.wire]?.includes('double'), r.wire).toBe(r.wire_type === 'double');
    }
  });

  it("the emulator's --host-timeout-ms takes the host timeout's range and default", () => {
    const source = read('firmware/host/cube_emulator.cpp');
    const host = table.find((r) => r.key === 'hostTimeoutMs');
    expect(host).toBeDefined();
    if (host === undefined) return;
    expect(source).toContain(`--host-timeout-ms must be ${range(host)}`);
    expect(source).toContain(`host timeout, ${range(host)} (default ${host.default})`);
    expect(source).toContain(`long host_timeout_ms = ${host.default};`);
  });

});

/** Sends one request to a fresh mock robot (the emulator in TypeScript); returns its reply. */
function mockSend(request: Record<string, unknown>, robot = new MockRobot()): Record<string, unknown> {
  const reply = robot.handle(new TextEncoder().encode(JSON.stringify(request)));
  return JSON.parse(new TextDecoder().decode(reply)) as Record<string, unknown>;
}

describe('the mock robot, held to tests/vectors/settings.json as the firmware is', () => {
  const vectors = buildSettingsVectors();

  it("replies hello's config with every wire field at its default, in the firmware's order", () => {
    const hello = mockSend({ cmd: 'hello' }) as { config: Record<string, unknown> };
    expect(Object.keys(hello.config)).toEqual(wireRows.map((r) => r.wire));
    for (const r of wireRows) expect(hello.config[r.wire], r.wire).toBe(r.default);
  });

  it('takes each set_config field at both ends and refuses just outside with RANGE_EXCEEDED', () => {
    for (const row of vectors.settings) {
      if (!('refused' in row) || row.wire === null) continue;
      for (const edge of [row.min, row.max]) {
        const reply = mockSend({ cmd: 'set_config', [row.wire]: edge }) as {
          config?: Record<string, unknown>;
        };
        expect(reply.config?.[row.wire], `${row.wire} = ${edge}`).toBe(edge);
      }
      for (const out of row.refused) {
        const reply = mockSend({ cmd: 'set_config', [row.wire]: out });
        expect(reply['error'], `${row.wire} = ${out}`).toMatchObject({ code: 'RANGE_EXCEEDED' });
      }
    }
  });

  it('runs a faster request at the speed ceiling', () => {
    const ceiling = vectors.speed_ceiling_steps_per_s;
    const robot = new MockRobot();
    mockSend({ cmd: 'set_config', max_speed_steps_per_s: ceiling }, robot);
    const move = mockSend({ cmd: 'move_steps', left: 4000, right: 4000, speed: 4096 }, robot);
    expect(move).toMatchObject({ ok: true, speed: ceiling, speed_clamped: true });
  });

  it("protocol-messages.json's speed ceiling case (run on the firmware too) is the table's", () => {
    const cases = (
      JSON.parse(read('tests/vectors/protocol-messages.json')) as {
        cases: Array<{ name: string; steps: Array<{ send?: Record<string, unknown> }> }>;
      }
    ).cases;
    const ceilingCase = cases.find((c) => c.name.startsWith('speed_ceiling_is_'));
    expect(ceilingCase?.name).toBe(`speed_ceiling_is_${vectors.speed_ceiling_steps_per_s}_steps_per_s`);
    expect(ceilingCase?.steps[0]?.send).toEqual({
      cmd: 'set_config',
      max_speed_steps_per_s: vectors.speed_ceiling_steps_per_s,
    });
  });
});

/** The docs' text, one entry per table row or paragraph (a paragraph's lines joined). */
function docUnits(): Array<{ file: string; text: string }> {
  const files = [
    'README.md',
    ...readdirSync(new URL('docs/', root))
      .filter((f) => f.endsWith('.md'))
      .map((f) => `docs/${f}`),
  ];
  return files.flatMap((file) =>
    read(file)
      .split(/\n\s*\n/)
      .flatMap((block) =>
        block.trimStart().startsWith('|') ? block.split('\n') : [block.replace(/\s*\n\s*/g, ' ')],
      )
      .map((text) => ({ file, text })),
  );
}

describe("the docs' settings", () => {
  const units = docUnits();

  it('protocol.md section 5.10 has one row per set_config field: type, range, default', () => {
    const doc = read('docs/protocol.md');
    const section = doc.slice(doc.indexOf('### 5.10 `set_config`'), doc.indexOf('### 5.11'));
    const rows = [...section.matchAll(/^\| `(\w+)` \| (\w+) \| ([\d.]+\.\.[\d.]+) \| ([\d.]+)/gm)];
    expect(
      rows.map(([, wire, type, r, def]) => ({ wire, type, range: r, default: Number(def) })),
    ).toEqual(
      setConfigRows.map((r) => ({
        wire: r.wire,
        type: r.integer ? 'int' : 'number',
        range: range(r),
        default: r.default,
      })),
    );
    const fixed = table.find((r) => r.set_by === 'hello');
    expect(section).toContain(`\`${fixed?.wire}\` (int, ${fixed?.default})`);
  });

  it("kinematics.md's set_config ranges row names every range with its unit", () => {
    const row = read('docs/kinematics.md')
      .split('\n')
      .find((l) => l.startsWith('| `set_config` ranges |'));
    expect(row).toBeDefined();
    for (const r of setConfigRows) expect(row, r.key).toContain(`${range(r)} ${r.unit}`);
  });

  it('every range written right after a wire field, a key or a flag is the table', () => {
    const names = (r: SettingRow): string[] => {
      const flag = r.wire === null ? [] : [`--${r.wire.replace(/_/g, '-')}`];
      return [...(r.wire === null ? [] : [`\`${r.wire}\``]), `\`${r.key}\``, ...flag];
    };
    const allNames = table.flatMap(names);
    let checked = 0;
    for (const { file, text } of units) {
      for (const r of table) {
        for (const name of names(r)) {
          for (let at = text.indexOf(name); at >= 0; at = text.indexOf(name, at + 1)) {
            // the words after the name, up to the next setting's name
            let after = text.slice(at + name.length, at + name.length + 80);
            for (const other of allNames) {
              const cut = after.indexOf(other);
              if (cut >= 0) after = after.slice(0, cut);
            }
            const found = /(-?[\d.]+)\.\.([\d.]+)/.exec(after);
            if (found === null) continue;
            checked += 1;
            expect(`${found[1]}..${found[2]}`, `${file}: ${text.slice(0, 120)}`).toBe(range(r));
          }
        }
      }
    }
    expect(checked).toBeGreaterThanOrEqual(5);
  });

  it('the speed ceiling and host timeout sentences of protocol.md, hardware.md agree', () => {
    const speed = table.find((r) => r.key === 'maxSpeedStepsPerS');
    const host = table.find((r) => r.key === 'hostTimeoutMs');
    if (speed === undefined || host === undefined) throw new Error('rows missing');
    const protocol = units.filter((u) => u.file === 'docs/protocol.md').map((u) => u.text);
    expect(protocol.join('\n')).toContain(
      `(settable ${range(speed)}, default ${speed.default})`,
    );
    expect(protocol.join('\n')).toContain(
      `default **${host.default} ms**, settable ${range(host)} ms`,
    );
    expect(read('docs/hardware.md')).toContain(
      `| max speed | ${speed.default} steps/s (4.71 cm/s) by default; settable ${range(speed)} |`,
    );
  });
});
