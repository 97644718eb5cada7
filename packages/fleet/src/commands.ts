import { z } from 'zod';
import { HAL_CALL_TABLE, HalError, V1_ROBOT, argsFromObject, invokeSpec } from '@hal/types';
import type { CallSpec, CallTable, HALToolResult, HardwareAbstractionLayer } from '@hal/types';

/*
 * A fleet command is a HAL call written as data, so a CLI, a config file or a browser demo can
 * send the same command to many robots. The HAL still validates every parameter against each
 * robot's own limits; this schema only checks the shape.
 */

/** The calls a fleet sends as commands: every locomotion command (motions and stop), and the LED. */
export function isFleetCall(spec: CallSpec): boolean {
  return (spec.subsystem === 'locomotion' && spec.kind !== 'value') || spec.name === 'setLED';
}

/** Parameters a fleet command may leave out, with the value sent for them. */
const FLEET_DEFAULTS: Readonly<Record<string, Readonly<Record<string, unknown>>>> = {
  moveTo: { z: 0 },
};

/** A parameter's schema with its type and description but none of one robot's limits. */
function shapeOnly(schema: z.ZodType): z.ZodType {
  if (schema instanceof z.ZodOptional) return shapeOnly(schema.unwrap() as z.ZodType).optional();
  const loose =
    schema instanceof z.ZodNumber
      ? z.number()
      : schema instanceof z.ZodString
        ? z.string()
        : schema;
  return schema.description === undefined ? loose : loose.describe(schema.description);
}

function commandSchema(spec: CallSpec): z.ZodObject {
  const params = spec.paramsSchema(V1_ROBOT) as z.ZodObject;
  const defaults = FLEET_DEFAULTS[spec.name] ?? {};
  const shape = Object.fromEntries(
    Object.entries(params.shape as Record<string, z.ZodType>).map(([name, field]) => {
      const loose = shapeOnly(field);
      return [name, name in defaults ? loose.optional() : loose];
    }),
  );
  return z.object({ kind: z.literal(spec.name), ...shape });
}

/** The schema of the fleet commands of a call table. */
export function fleetCommandSchema(table: CallTable = HAL_CALL_TABLE): z.ZodType<FleetCommand> {
  const options = table.filter(isFleetCall).map(commandSchema);
  return z
    .discriminatedUnion('kind', options as [z.ZodObject, ...z.ZodObject[]])
    .describe(
      'One HAL call, as data, for every member of a fleet',
    ) as unknown as z.ZodType<FleetCommand>;
}

/** One HAL call, as data: its name as `kind`, its parameters by name. */
export type FleetCommand = { kind: string } & Record<string, unknown>;

/** The HAL's own fleet commands (see {@link fleetCommandSchema}). */
export const FleetCommandSchema: z.ZodType<FleetCommand> = fleetCommandSchema();

/** Checks a command; a bad one is an INVALID_PARAMETER HalError naming what is wrong. */
export function parseFleetCommand(
  input: unknown,
  schema: z.ZodType<FleetCommand> = FleetCommandSchema,
): FleetCommand {
  const parsed = schema.safeParse(input);
  if (parsed.success) return parsed.data;
  const issues = parsed.error.issues
    .map((i) => `${i.path.length > 0 ? i.path.join('.') : 'command'}: ${i.message}`)
    .join('; ');
  throw new HalError('INVALID_PARAMETER', `not a fleet command (${issues})`, {
    details: { issues: parsed.error.issues.map((i) => ({ path: i.path, message: i.message })) },
  });
}

/** Runs a command on one HAL through its own calls (and so its own validation). */
export async function runFleetCommand(
  hal: HardwareAbstractionLayer,
  command: FleetCommand,
  table: CallTable = HAL_CALL_TABLE,
): Promise<HALToolResult> {
  const spec = table.find((entry) => entry.name === command.kind && isFleetCall(entry));
  if (spec === undefined) {
    throw new HalError('INVALID_PARAMETER', `not a fleet command kind: "${command.kind}"`);
  }
  const named = { ...FLEET_DEFAULTS[spec.name] };
  for (const [key, value] of Object.entries(command)) if (value !== undefined) named[key] = value;
  return (await invokeSpec(hal, spec, argsFromObject(spec, named))) as HALToolResult;
}
