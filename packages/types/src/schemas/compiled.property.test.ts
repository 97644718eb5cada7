import { fc, it } from '@fast-check/vitest';
import { describe, expect } from 'vitest';
import { z } from 'zod';
import { RobotConfigSchema, V1_ROBOT } from '../robot-config.js';
import type { RobotConfig } from '../robot-config.js';
import { createCallSchemas } from './calls.js';
import { compileCallSchemas } from './compiled.js';
import { anyInput, jsonSchemaOf, validObject } from './schema-inputs.fixture.js';

// The compiled call schemas the HAL boundary parses with, against the ordinary ones, over every
// call schema of three robots: for every input, the same verdict, a deep-equal output when both
// accept and the same issues when both refuse (so the compiled path is never less strict, never
// gives another value and never another error). And zod does compile every one of them, so the
// compiled path is the one actually used.

const ROBOTS: Record<string, RobotConfig> = {
  'the V1 robot': V1_ROBOT,
  // a larger, faster robot: other bounds, some of them fractional
  'a larger robot': RobotConfigSchema.parse({
    stepsPerRevolution: 200,
    wheelDiameterCm: 12.7,
    wheelBaseCm: 31.3,
    maxSpeedStepsPerS: 2048,
    minSpeedStepsPerS: 7,
    maxStepsPerCommand: 12_345,
    maxDriveDurationMs: 1500,
    workspaceHalfExtentM: 2.5,
  }),
  // a robot whose slowest and top speeds are the same: a range of one value
  'a one-speed robot': RobotConfigSchema.parse({
    minSpeedStepsPerS: 300,
    maxSpeedStepsPerS: 300,
    workspaceHalfExtentM: 0.001,
    maxDriveDurationMs: 1,
  }),
};

/** What a parse came to: the output, the issues, or what it threw. */
function outcome(schema: z.ZodType, input: unknown): unknown {
  try {
    const parsed = schema.safeParse(input);
    return parsed.success ? { data: parsed.data } : { issues: parsed.error.issues };
  } catch (thrown) {
    return { threw: String(thrown) };
  }
}

for (const [robot, config] of Object.entries(ROBOTS)) {
  const schemas = createCallSchemas(config);
  const compiled = compileCallSchemas(schemas);

  describe(`the compiled call schemas of ${robot}`, () => {
    it('are compiled by zod, every one (zod hands a schema it cannot compile back unchanged)', () => {
      for (const [name, schema] of Object.entries(schemas)) {
        expect(() => z.compile(schema as z.ZodType, { strict: true }), name).not.toThrow();
        expect(compiled[name as keyof typeof schemas], name).not.toBe(schema);
      }
    });

    for (const [name, schema] of Object.entries(schemas) as [string, z.ZodType][]) {
      const fast = compiled[name as keyof typeof schemas] as z.ZodType;

      it.prop([anyInput(schema)], { numRuns: 400 })(
        `parse ${name} arguments as the ordinary schema does: verdict, output and issues`,
        (input) => {
          expect(outcome(fast, input)).toStrictEqual(outcome(schema, input));
        },
      );

      it.prop([validObject(jsonSchemaOf(schema))], { numRuns: 200 })(
        `accept every ordinary valid ${name} call with the ordinary output`,
        (input) => {
          expect(fast.parse(input)).toStrictEqual(schema.parse(input));
        },
      );
    }
  });
}

describe('compileCallSchemas', () => {
  it.prop([fc.integer({ min: 0, max: 255 })])(
    'strips unknown keys and keeps an optional key present as undefined, as zod does',
    (r) => {
      const { setLED } = compileCallSchemas(createCallSchemas(V1_ROBOT));
      const input = { r, g: 0, b: 255, pattern: undefined, extra: 1 };
      expect(setLED.parse(input)).toStrictEqual({ r, g: 0, b: 255, pattern: undefined });
    },
  );

  it('leaves the source schemas as they were', () => {
    const schemas = createCallSchemas(V1_ROBOT);
    const drive = schemas.drive;
    compileCallSchemas(schemas);
    expect(schemas.drive).toBe(drive);
    expect(drive.safeParse({ left: 300, right: 0 }).success).toBe(false);
  });
});
