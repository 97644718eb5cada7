import { describe, expect, it } from 'vitest';
import {
  NavigationDecisionSchema,
  createDecisionSchema,
  decisionJsonSchema,
  parseDecision,
} from './schema.js';

describe('NavigationDecisionSchema', () => {
  it('accepts each of the four actions with the goal flag and the reasoning', () => {
    for (const action of [
      { type: 'MOVE_TO', x: 1, y: -0.5 },
      { type: 'EXPLORE' },
      { type: 'ROTATE_TO', yaw_deg: -90 },
      { type: 'STOP' },
    ]) {
      const decision = { reasoning: 'because', action, goal_reached: action.type === 'STOP' };
      expect(NavigationDecisionSchema.parse(decision)).toEqual(decision);
    }
  });

  it('refuses non-finite coordinates, unknown actions, missing fields and extra action fields', () => {
    const base = { reasoning: 'r', goal_reached: false };
    expect(parseDecision({ ...base, action: { type: 'MOVE_TO', x: Number.NaN, y: 0 } }).ok).toBe(
      false,
    );
    expect(parseDecision({ ...base, action: { type: 'MOVE_TO', x: Infinity, y: 0 } }).ok).toBe(
      false,
    );
    expect(parseDecision({ ...base, action: { type: 'FLY' } }).ok).toBe(false);
    expect(parseDecision({ reasoning: 'r', action: { type: 'STOP' } }).ok).toBe(false);
    expect(parseDecision({ ...base, action: { type: 'ROTATE_TO', yaw_deg: 720 } }).ok).toBe(false);
    const problem = parseDecision({ ...base, action: { type: 'MOVE_TO', x: 1 } });
    expect(problem).toEqual({ ok: false, problem: expect.stringContaining('action') });
  });

  it('limits MOVE_TO targets to the given bounds', () => {
    const bounds = { minX: -2.5, maxX: 2.5, minY: -2.5, maxY: 2.5 };
    const inside = {
      reasoning: 'r',
      goal_reached: false,
      action: { type: 'MOVE_TO', x: 2, y: -2 },
    };
    const outside = { ...inside, action: { type: 'MOVE_TO', x: 3, y: 0 } };
    expect(parseDecision(inside, bounds).ok).toBe(true);
    expect(parseDecision(outside, bounds).ok).toBe(false);
    expect(createDecisionSchema(bounds).safeParse(outside).success).toBe(false);
  });

  it('documents ROTATE_TO yaw_deg as an absolute, counter-clockwise heading', () => {
    const schema = decisionJsonSchema() as {
      properties: { action: { anyOf: { properties: Record<string, { description?: string }> }[] } };
    };
    const rotate = schema.properties.action.anyOf.find((member) => 'yaw_deg' in member.properties);
    const text = rotate?.properties['yaw_deg']?.description ?? '';
    expect(text).toContain('Absolute heading');
    expect(text).toContain('counter-clockwise from +x');
    expect(text).toContain('not a relative turn');
  });
});

describe('decisionJsonSchema', () => {
  it('is a strict JSON Schema object with the actions as anyOf and every field required', () => {
    const schema = decisionJsonSchema({ minX: -1, maxX: 1, minY: -2, maxY: 2 }) as Record<
      string,
      unknown
    > & {
      properties: Record<string, { anyOf?: Record<string, unknown>[] }>;
    };
    expect(schema['$schema']).toBeUndefined();
    expect(schema['type']).toBe('object');
    expect(schema['additionalProperties']).toBe(false);
    expect(schema['required']).toEqual(['reasoning', 'action', 'goal_reached']);
    const members = schema.properties['action']?.anyOf ?? [];
    expect(members.map((m) => (m['properties'] as { type: { const: string } }).type.const)).toEqual(
      ['MOVE_TO', 'EXPLORE', 'ROTATE_TO', 'STOP'],
    );
    for (const m of members) expect(m['additionalProperties']).toBe(false);
    const moveTo = members[0]?.['properties'] as Record<
      string,
      { minimum?: number; maximum?: number }
    >;
    expect(moveTo['y']).toMatchObject({ minimum: -2, maximum: 2 });
  });
});
