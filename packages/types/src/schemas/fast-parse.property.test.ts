import { fc, it } from '@fast-check/vitest';
import { describe, expect } from 'vitest';
import { RobotConfigSchema, V1_ROBOT } from '../robot-config.js';
import type { RobotConfig } from '../robot-config.js';
import { createCallSchemas } from './calls.js';
import { compileFastParsers } from './fast-parse.js';
import { anyInput, jsonSchemaOf, validObject } from './schema-inputs.fixture.js';

// The fast path against its definition, zod, over every call schema of three robots: whatever
// the fast path accepts, zod accepts with a deep-equal output (so it is never less strict and
// never gives another value); whatever zod refuses, the fast path refuses. And it does take the
// ordinary valid calls of every schema it models, so it is the path actually used.

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

/** The calls the fast path leaves wholly to zod, and why. */
const FALLS_BACK = [
  // its reason goes through z.preprocess (any value becomes a stored reason): zod decides
  'emergencyStop',
];

for (const [robot, config] of Object.entries(ROBOTS)) {
  const schemas = createCallSchemas(config);
  const fast = compileFastParsers(schemas);

  describe(`the fast path of the call schemas of ${robot}`, () => {
    it('models every call schema except those it names as falling back to zod', () => {
      const missing = Object.keys(schemas).filter((name) => !(name in fast));
      expect(missing).toStrictEqual(FALLS_BACK);
    });

    for (const [name, schema] of Object.entries(schemas)) {
      const parse = fast[name as keyof typeof schemas];
      if (parse === undefined) continue;

      it.prop([anyInput(schema)], { numRuns: 400 })(
        `accepts ${name} arguments only when zod does, with zod's output`,
        (input) => {
          const result = schema.safeParse(input);
          const output = parse(input);
          if (output !== undefined) {
            expect(result.success).toBe(true);
            expect(output).toStrictEqual(result.data);
          }
          if (!result.success) expect(output).toBeUndefined();
        },
      );

      it.prop([validObject(jsonSchemaOf(schema))], { numRuns: 200 })(
        `takes every ordinary valid ${name} call itself`,
        (input) => {
          expect(parse(input)).toStrictEqual(schema.parse(input));
        },
      );
    }
  });
}

describe('compileFastParsers', () => {
  it.prop([fc.integer({ min: 0, max: 255 })])(
    'strips unknown keys and keeps an optional key present as undefined, as zod does',
    (r) => {
      const setLED = createCallSchemas(V1_ROBOT).setLED;
      const parse = compileFastParsers({ setLED }).setLED!;
      const input = { r, g: 0, b: 255, pattern: undefined, extra: 1 };
      expect(parse(input)).toStrictEqual({ r, g: 0, b: 255, pattern: undefined });
      expect(parse(input)).toStrictEqual(setLED.parse(input));
    },
  );
});
