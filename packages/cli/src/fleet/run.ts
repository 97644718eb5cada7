// `hal fleet run`: one command to every device at once (synchronized), or a leader driven by one
// command while the others keep a formation around it (leader-follower).
import { formationOffsets } from '@hal/fleet';
import type { FleetCommand, FleetReport, FormationReport, FormationShape } from '@hal/fleet';
import { runFleetCommand } from '@hal/fleet';
import type { DeviceManager } from '@hal/fleet/node';
import { CliError } from '../cli-error.js';
import { progress } from '../io.js';
import type { CliIO, GlobalOptions } from '../io.js';

export interface LeaderFollowerCliOptions {
  leader: string;
  formation: FormationShape;
  spacing: number;
  toleranceM: number;
  settleTimeoutMs: number;
}

/** Runs `command` on every managed device in the same tick. */
export function runSynchronized(
  manager: DeviceManager,
  command: FleetCommand,
  timeoutMs: number,
  io: CliIO,
  global: GlobalOptions,
): Promise<FleetReport> {
  progress(io, global, `synchronized ${command.kind} on ${manager.devices.length} device(s)...`);
  return manager.fleet.synchronized(command, { timeoutMs });
}

/**
 * Starts the formation, runs `command` on the leader, and waits for the followers to settle in
 * their slots (or the formation to end otherwise). An abort (Ctrl-C) stops the formation.
 */
export async function runLeaderFollower(
  manager: DeviceManager,
  command: FleetCommand,
  options: LeaderFollowerCliOptions,
  io: CliIO,
  global: GlobalOptions,
): Promise<{ leader: FleetReport['results'][number]; formation: FormationReport }> {
  if (!manager.devices.includes(options.leader)) {
    throw new CliError(
      'USAGE',
      `--leader "${options.leader}" is not one of the devices (${manager.devices.join(', ')})`,
    );
  }
  const followers = manager.devices.filter((d) => d !== options.leader);
  if (followers.length === 0)
    throw new CliError('USAGE', 'leader-follower needs at least two devices');
  const formation = await manager.fleet.leaderFollower({
    leader: options.leader,
    formation: formationOffsets(options.formation, followers, options.spacing),
    toleranceM: options.toleranceM,
    settleTimeoutMs: options.settleTimeoutMs,
  });
  const onAbort = (): void => void formation.stop();
  io.signal.addEventListener('abort', onAbort, { once: true });
  try {
    progress(
      io,
      global,
      `formation ${options.formation} (${options.spacing} m): ${followers.length} follower(s) of ${options.leader}`,
    );
    const leader = manager.fleet.hal(options.leader);
    const startedAt = Date.now();
    const result = await runFleetCommand(leader, command);
    progress(
      io,
      global,
      `leader ${command.kind}: ${result.success ? 'done' : `${result.code}`}; followers settling...`,
    );
    if (!result.success) await formation.stop();
    const report = await formation.done;
    return { leader: { device: options.leader, result, issuedAt: startedAt }, formation: report };
  } finally {
    io.signal.removeEventListener('abort', onAbort);
  }
}
