// The guard on the command line: on by default wherever a model, a network or a person drives
// (`hal agent`, `hal mcp`, `hal serve`, `hal eval`, `hal drive`, `hal teleop`); `--no-guard` turns
// it off, `--guard-standoff` sets how far before an obstacle it stops. @hal/perception guards.
import { GuardEventSchema, guardHal } from '@hal/perception';
import type { GuardedHAL, GuardStatus } from '@hal/perception';
import type { McapRecorder, NamedJsonSchema } from '@hal/recorder';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { Command } from 'commander';
import { z } from 'zod';
import type { CliIO } from './io.js';
import { cliLogger } from './logger.js';
import { distanceArg } from './values.js';

/** The guard options as commander parses them (`guard` is false with --no-guard). */
export interface GuardCliOptions {
  guard?: boolean;
  guardStandoff?: number;
}

/** Adds --no-guard and --guard-standoff to `command`. */
export function addGuardOptions(command: Command): Command {
  return command
    .option(
      '--no-guard',
      'turn the guard off: nothing stops the robot before an obstacle it sees ahead',
    )
    .option(
      '--guard-standoff <distance>',
      "guard: stop this far before an obstacle ahead of the body's front (metres, or 10cm; default 10cm)",
      distanceArg('--guard-standoff', { min: 0, aboveMin: true, max: 5 }),
    );
}

/** The guard settings the parsed options ask for, or undefined with --no-guard. */
export function guardSettingsFromOptions(
  options: GuardCliOptions,
): { standoffM?: number } | undefined {
  if (options.guard === false) return undefined;
  return options.guardStandoff === undefined ? {} : { standoffM: options.guardStandoff };
}

/** Targets reached over the network: they are guarded where they are served (`hal serve`). */
const SERVED_ELSEWHERE: ReadonlySet<string> = new Set(['ws', 'nats']);

/**
 * `hal` guarded as the options ask (unguarded with --no-guard), its warnings (it cannot see, a
 * reverse passes unwatched) written as the HAL's are. A robot reached over the network (`--ws`,
 * `--nats`/`--device`) is guarded where it is served, not here again: each look would cross the
 * network, and the served robot's own guard is nearer to it.
 */
export function guardFromOptions(
  hal: HardwareAbstractionLayer,
  options: GuardCliOptions,
  io: CliIO,
  json: boolean,
  target?: { kind: string },
): { hal: HardwareAbstractionLayer; guard: GuardedHAL | undefined } {
  const settings = guardSettingsFromOptions(options);
  if (settings === undefined) return { hal, guard: undefined };
  if (target !== undefined && SERVED_ELSEWHERE.has(target.kind)) return { hal, guard: undefined };
  const guard = guardHal(hal, { ...settings, logger: cliLogger(io, json) });
  return { hal: guard, guard };
}

/** What a run reports of its guard: its status, or `{ off: true }` with --no-guard. */
export function guardReport(guard: GuardedHAL | undefined): GuardStatus | { off: true } {
  return guard === undefined ? { off: true } : guard.status();
}

/** A line for people of what the guard did, when it did anything worth saying. */
export function guardText(report: GuardStatus | { off: true }): string | undefined {
  if ('off' in report) return undefined;
  if (report.warning !== undefined) return `guard: ${report.warning}`;
  const last = report.lastStop;
  if (report.stops === 0 || last === undefined) return undefined;
  const ahead = `${last.atEdge ? 'at most ' : ''}${last.distanceM} m ahead (${last.source})`;
  return `guard: ${report.stops} motion(s) stopped or refused before an obstacle; the last ${ahead}`;
}

/** The topic of a recording the guard's events go to. */
export const GUARD_TOPIC = '/hal/guard';

/** The schema of {@link GUARD_TOPIC}'s messages. */
export const GUARD_EVENT: NamedJsonSchema = {
  name: 'hal.GuardEvent',
  schema: z.toJSONSchema(GuardEventSchema, { io: 'input', unrepresentable: 'any' }),
};

/**
 * Records what `guard` does (its stops, blind stops, motions it could not watch, that it cannot
 * see) on {@link GUARD_TOPIC} of `recorder`, beside the calls; nothing without either. Returns
 * the end of it.
 */
export function recordGuard(
  guard: GuardedHAL | undefined,
  recorder: McapRecorder | undefined,
): () => void {
  if (guard === undefined || recorder === undefined) return () => undefined;
  recorder.channel(GUARD_TOPIC, GUARD_EVENT);
  return guard.onEvent((event) => recorder.write(GUARD_TOPIC, event));
}
