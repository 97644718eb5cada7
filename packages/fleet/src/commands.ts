import { z } from 'zod';
import { HalError } from '@hal/types';
import type { HALToolResult, HardwareAbstractionLayer } from '@hal/types';

/*
 * A fleet command is a HAL call written as data, so a CLI, a config file or a browser demo can
 * send the same command to many robots. The HAL still validates every parameter against each
 * robot's own limits; this schema only checks the shape.
 */
export const FleetCommandSchema = z
  .discriminatedUnion('kind', [
    z.object({
      kind: z.literal('drive'),
      left: z.number().describe('Left wheel power, -255..255'),
      right: z.number().describe('Right wheel power, -255..255'),
      durationMs: z.number().optional().describe('Stop after this many ms'),
    }),
    z.object({
      kind: z.literal('moveTo'),
      x: z.number().describe('Target x, metres (world frame)'),
      y: z.number().describe('Target y, metres'),
      z: z.number().optional().describe('Target z, metres (default 0)'),
      speed: z.number().optional().describe('Cruise speed, m/s'),
    }),
    z.object({
      kind: z.literal('rotate'),
      direction: z.enum(['left', 'right']),
      degrees: z.number().describe('How far, degrees, > 0'),
    }),
    z.object({
      kind: z.literal('moveForward'),
      distanceCm: z.number().describe('How far, cm, > 0'),
    }),
    z.object({
      kind: z.literal('moveBackward'),
      distanceCm: z.number().describe('How far, cm, > 0'),
    }),
    z.object({ kind: z.literal('stop') }),
    z.object({
      kind: z.literal('setLED'),
      r: z.number(),
      g: z.number(),
      b: z.number(),
      pattern: z.enum(['solid', 'blink', 'pulse']).optional(),
    }),
  ])
  .describe('One HAL call, as data, for every member of a fleet');

/** One HAL call, as data (see {@link FleetCommandSchema}). */
export type FleetCommand = z.infer<typeof FleetCommandSchema>;

/** The command kinds a fleet understands. */
export const FLEET_COMMAND_KINDS = [
  'drive',
  'moveTo',
  'rotate',
  'moveForward',
  'moveBackward',
  'stop',
  'setLED',
] as const satisfies readonly FleetCommand['kind'][];

/** Checks a command; a bad one is an INVALID_PARAMETER HalError naming what is wrong. */
export function parseFleetCommand(input: unknown): FleetCommand {
  const parsed = FleetCommandSchema.safeParse(input);
  if (parsed.success) return parsed.data;
  const issues = parsed.error.issues
    .map((i) => `${i.path.length > 0 ? i.path.join('.') : 'command'}: ${i.message}`)
    .join('; ');
  throw new HalError('INVALID_PARAMETER', `not a fleet command (${issues})`, {
    details: { issues: parsed.error.issues.map((i) => ({ path: i.path, message: i.message })) },
  });
}

/** Runs a command on one HAL through its own calls (and so its own validation). */
export function runFleetCommand(
  hal: HardwareAbstractionLayer,
  command: FleetCommand,
): Promise<HALToolResult> {
  const loco = hal.locomotion;
  switch (command.kind) {
    case 'drive':
      return loco.drive(command.left, command.right, command.durationMs);
    case 'moveTo':
      return loco.moveTo(command.x, command.y, command.z ?? 0, command.speed);
    case 'rotate':
      return loco.rotate(command.direction, command.degrees);
    case 'moveForward':
      return loco.moveForward(command.distanceCm);
    case 'moveBackward':
      return loco.moveBackward(command.distanceCm);
    case 'stop':
      return loco.stop();
    case 'setLED':
      return hal.communication.setLED(command.r, command.g, command.b, command.pattern);
  }
}
