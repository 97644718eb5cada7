import { z } from 'zod';
import { ConnectionConfigSchema, HalError, RobotConfigSchema } from '@hal/types';
import { FLEET_MODES } from '../report.js';

const DeviceIdSchema = z
  .string()
  .regex(/^[A-Za-z0-9_-]{1,64}$/, 'device ids are 1..64 of letters, digits, "-" and "_"')
  .describe('Unique device id within the fleet (its NATS address too)');

const StartSchema = z
  .object({ x: z.number(), y: z.number(), yaw: z.number().default(0) })
  .describe('Start pose, metres and radians');

/** A simulated robot: a SimulationHAL in a named world (devices naming the same world share it). */
export const SimulatedDeviceSchema = z.object({
  type: z.literal('simulated'),
  id: DeviceIdSchema,
  world: z.string().min(1).default('default').describe('Name of the shared world to live in'),
  start: StartSchema.optional(),
  robot: RobotConfigSchema.partial().optional().describe('Geometry and limits, default V1'),
  clock: z
    .enum(['realtime', 'fast'])
    .default('realtime')
    .describe(
      'realtime: the world runs on the wall clock (robots move together); fast: each motion is computed at once',
    ),
  realtimeSpeed: z
    .number()
    .gt(0)
    .max(100)
    .default(1)
    .describe('realtime clock: simulated seconds per wall-clock second'),
});

/** A physical robot over WiFi UDP or serial: a PhysicalHAL. */
export const PhysicalDeviceSchema = z.object({
  type: z.literal('physical'),
  id: DeviceIdSchema,
  connection: ConnectionConfigSchema,
  robot: RobotConfigSchema.partial().optional(),
});

/** A device served on NATS by a gateway (`serveHalOnNats`): a NatsHAL. */
export const NatsDeviceSchema = z.object({
  type: z.literal('nats'),
  id: DeviceIdSchema,
  deviceId: DeviceIdSchema.optional().describe(
    'Its id on NATS (hal.v1.dev.{deviceId}...), default `id`',
  ),
  callTimeoutMs: z.number().int().min(100).max(600_000).optional(),
});

export const DeviceConfigSchema = z
  .discriminatedUnion('type', [SimulatedDeviceSchema, PhysicalDeviceSchema, NatsDeviceSchema])
  .describe('One device of the fleet');

/** NATS servers and credentials for the devices of type "nats". */
export const FleetNatsSchema = z.object({
  servers: z.union([z.string().min(1), z.array(z.string().min(1)).min(1)]),
  user: z.string().optional(),
  pass: z.string().optional(),
  token: z.string().optional(),
});

export const FleetConfigSchema = z
  .object({
    mode: z.enum(FLEET_MODES).default('independent').describe('The fleet mode tools start in'),
    devices: z.array(DeviceConfigSchema).default([]),
    nats: FleetNatsSchema.optional().describe(
      'NATS servers for the devices of type "nats" (or give the manager an open connection)',
    ),
    telemetryRateHz: z
      .number()
      .gt(0)
      .max(50)
      .default(2)
      .describe('How often each device is read (pose, safety), Hz'),
    offlineAfterMs: z
      .number()
      .int()
      .min(100)
      .max(600_000)
      .default(3000)
      .describe('A device is offline after this long without a successful read, ms'),
  })
  .superRefine((config, ctx) => {
    const seen = new Set<string>();
    config.devices.forEach((d, i) => {
      if (seen.has(d.id)) {
        ctx.addIssue({
          code: 'custom',
          path: ['devices', i, 'id'],
          message: `duplicate id "${d.id}"`,
        });
      }
      seen.add(d.id);
    });
  });

export type SimulatedDeviceConfig = z.infer<typeof SimulatedDeviceSchema>;
export type PhysicalDeviceConfig = z.infer<typeof PhysicalDeviceSchema>;
export type NatsDeviceConfig = z.infer<typeof NatsDeviceSchema>;
export type DeviceConfig = z.infer<typeof DeviceConfigSchema>;
export type DeviceConfigInput = z.input<typeof DeviceConfigSchema>;
export type FleetConfig = z.infer<typeof FleetConfigSchema>;
export type FleetConfigInput = z.input<typeof FleetConfigSchema>;

function issuesText(error: z.ZodError): string {
  return error.issues
    .map((i) => `${i.path.length > 0 ? i.path.join('.') : '(root)'}: ${i.message}`)
    .join('; ');
}

/** Checks a fleet configuration; a bad one is INVALID_PARAMETER listing every problem by path. */
export function parseFleetConfig(input: unknown): FleetConfig {
  const parsed = FleetConfigSchema.safeParse(input);
  if (parsed.success) return parsed.data;
  throw new HalError('INVALID_PARAMETER', `fleet config: ${issuesText(parsed.error)}`, {
    details: { issues: parsed.error.issues.map((i) => ({ path: i.path, message: i.message })) },
  });
}

/** Checks one device's configuration (INVALID_PARAMETER naming the field). */
export function parseDeviceConfig(input: unknown): DeviceConfig {
  const parsed = DeviceConfigSchema.safeParse(input);
  if (parsed.success) return parsed.data;
  throw new HalError('INVALID_PARAMETER', `device config: ${issuesText(parsed.error)}`, {
    details: { issues: parsed.error.issues.map((i) => ({ path: i.path, message: i.message })) },
  });
}
