// `hal fleet`: the devices on NATS, or those of a config file, as one fleet: list them, read
// their health, e-stop them all, and run the fleet modes (synchronized, leader-follower).
import { FORMATION_SHAPES } from '@hal/fleet';
import type { FormationShape } from '@hal/fleet';
import { Command, Option } from 'commander';
import { CliError } from '../cli-error.js';
import { parseCommandSpec, COMMAND_SPEC_HELP } from '../fleet/command-spec.js';
import { startFleetRecording } from '../fleet/fleet-recording.js';
import { openFleetSession } from '../fleet/fleet-session.js';
import type { FleetCliOptions, FleetSessionExtras } from '../fleet/fleet-session.js';
import { formatFormation, formatHealth, formatReport } from '../fleet/format.js';
import { runLeaderFollower, runSynchronized } from '../fleet/run.js';
import { resolveRunMode, RUN_MODES } from '../fleet/run-mode.js';
import type { RunMode } from '../fleet/run-mode.js';
import { emit } from '../io.js';
import { addNatsOptions, deviceIdArg } from '../nats-options.js';
import { distanceArg, integerArg } from '../values.js';
import type { CommandContext, RegisterCommand } from './context.js';

const collectDevice = (value: string, previous: string[] = []): string[] => [
  ...previous,
  deviceIdArg(value),
];

/** A fleet subcommand with the shared device and NATS options. */
function fleetSubcommand(name: string, description: string): Command {
  const command = new Command(name)
    .description(description)
    .option(
      '--config <file>',
      'a fleet config file (JSON: simulated, physical and NATS devices); no discovery',
    )
    .option(
      '--device <id>',
      'a device on NATS, or one of the config file (repeat for more; default: every device that announces itself, or all in the file)',
      collectDevice,
    )
    .addOption(
      new Option('--discover-ms <ms>', 'how long to listen for announcements')
        .default(6000)
        .argParser(integerArg('--discover-ms', 1, 600_000)),
    )
    .addOption(
      new Option(
        '--offline-after-ms <ms>',
        "a device is offline after this long without an answer (default 3000, or the config file's)",
      ).argParser(integerArg('--offline-after-ms', 1, 600_000)),
    );
  return addNatsOptions(command);
}

/** Runs `body` with an open fleet session, closing it whatever happens. */
async function withSession<T>(
  options: FleetCliOptions,
  ctx: CommandContext,
  body: (session: Awaited<ReturnType<typeof openFleetSession>>) => Promise<T>,
  extras: FleetSessionExtras = {},
): Promise<T> {
  const session = await openFleetSession(options, ctx.io, ctx.global(), extras);
  try {
    return await body(session);
  } finally {
    await session.close();
  }
}

function failIfAny(what: string, failed: string[]): void {
  if (failed.length > 0) throw new CliError('FAILED', `${what} failed on ${failed.join(', ')}`);
}

/** What a fleet run ends with: its report, how to print it, and the failure to exit with. */
interface RunOutcome {
  value: object;
  text: () => string;
  failure?: CliError;
}

export const registerFleet: RegisterCommand = (program, ctx) => {
  const fleet = program
    .command('fleet')
    .description(
      'several robots (on NATS, or from --config) as one fleet: devices, health, e-stop and the fleet modes',
    );

  fleet.addCommand(
    fleetSubcommand(
      'devices',
      'list the devices, their type, mode, capabilities and whether they answer',
    ).action((options: FleetCliOptions) =>
      withSession(options, ctx, async ({ manager }) => {
        const devices = manager.health().map((h) => {
          const info = manager.createDeviceHAL(h.device).getDeviceInfo();
          return {
            device: h.device,
            online: h.online,
            type: info.type,
            mode: info.mode,
            capabilities: info.capabilities,
          };
        });
        emit(ctx.io, ctx.global(), { devices }, () =>
          devices
            .map(
              (d) =>
                `${d.device}  ${d.online ? 'online' : 'OFFLINE'}  ${d.type} (${d.mode})  ${d.capabilities.join(' ')}`,
            )
            .join('\n'),
        );
      }),
    ),
  );

  fleet.addCommand(
    fleetSubcommand('health', 'every device: online, e-stop, pose, faults').action(
      (options: FleetCliOptions) =>
        withSession(options, ctx, async ({ manager }) => {
          const health = manager.health();
          emit(ctx.io, ctx.global(), { health }, () => formatHealth(health));
        }),
    ),
  );

  fleet.addCommand(
    fleetSubcommand('estop', 'emergency-stop every device at once (latched until reset)')
      .argument('[reason]', 'why, stored with the latch', 'fleet e-stop')
      .action((reason: string, options: FleetCliOptions) =>
        withSession(options, ctx, async ({ manager }) => {
          const report = await manager.emergencyStop(reason);
          emit(ctx.io, ctx.global(), report, () => formatReport('e-stop', report));
          failIfAny('the e-stop', report.failed);
        }),
      ),
  );

  fleet.addCommand(
    fleetSubcommand('reset', "reset every device's emergency stop").action(
      (options: FleetCliOptions) =>
        withSession(options, ctx, async ({ manager }) => {
          const report = await manager.fleet.resetEmergencyStop();
          emit(ctx.io, ctx.global(), report, () => formatReport('reset', report));
          failIfAny('the reset', report.failed);
        }),
    ),
  );

  fleet.addCommand(
    fleetSubcommand(
      'run',
      'run a fleet mode: one command to all, or a leader with followers in formation',
    )
      .addOption(
        new Option(
          '--mode <mode>',
          "the fleet mode (default: the config file's, when it is one of these)",
        ).choices([...RUN_MODES]),
      )
      .requiredOption('--command <command>', `what to do: ${COMMAND_SPEC_HELP}`)
      .addOption(
        new Option('--timeout-ms <ms>', 'per-device wait (synchronized)')
          .default(60_000)
          .argParser(integerArg('--timeout-ms', 1, 3_600_000)),
      )
      .option('--leader <id>', 'leader-follower: the leader (runs --command)', deviceIdArg)
      .addOption(
        new Option('--formation <shape>', 'leader-follower: the formation')
          .choices([...FORMATION_SHAPES])
          .default('column'),
      )
      .addOption(
        new Option('--spacing <distance>', 'leader-follower: spacing (metres, or 30cm)')
          .default(0.3)
          .argParser(distanceArg('--spacing', { min: 0, aboveMin: true })),
      )
      .addOption(
        new Option('--tolerance <distance>', 'leader-follower: slot tolerance (metres, or 3cm)')
          .default(0.03)
          .argParser(distanceArg('--tolerance', { min: 0, aboveMin: true })),
      )
      .addOption(
        new Option(
          '--settle-timeout-ms <ms>',
          'leader-follower: how long followers may take to settle',
        )
          .default(120_000)
          .argParser(integerArg('--settle-timeout-ms', 1, 3_600_000)),
      )
      .option(
        '--record <file>',
        'record the run into this MCAP file: every robot on its own channels, under /<device> (see docs/recording.md)',
      )
      .addOption(
        new Option(
          '--overwrite',
          'replace the --record file when it exists (default: refuse, before starting)',
        ),
      )
      .action(
        async (
          options: FleetCliOptions &
            ModeOptions & {
              mode?: RunMode;
              command: string;
              record?: string;
              overwrite?: boolean;
            },
        ) => {
          const command = parseCommandSpec(options.command);
          const mode = await resolveRunMode(options.mode, options.config);
          if (mode === 'leader-follower' && options.leader === undefined) {
            throw new CliError('USAGE', 'leader-follower mode needs --leader <id>');
          }
          // a file that cannot be written is refused before any robot is touched
          const recording =
            options.record === undefined
              ? undefined
              : await startFleetRecording(options.record, ctx.io, {
                  json: ctx.global().json,
                  overwrite: options.overwrite === true,
                });
          let outcome: RunOutcome;
          let recorded: Awaited<ReturnType<NonNullable<typeof recording>['close']>> | undefined;
          try {
            outcome = await withSession(
              options,
              ctx,
              ({ manager }) => {
                recording?.describe({ mode, command: options.command, devices: manager.devices });
                return runMode(manager, mode, command, options, ctx);
              },
              recording === undefined ? {} : { wrapDevice: recording.wrapDevice },
            );
          } finally {
            // after the session closed: the devices' cleanups are in the file
            recorded = await recording?.close();
          }
          emit(
            ctx.io,
            ctx.global(),
            { ...outcome.value, ...(recorded === undefined ? {} : { recording: recorded }) },
            () =>
              [
                outcome.text(),
                ...(recorded === undefined
                  ? []
                  : [
                      `recorded ${recorded.written} messages to ${recorded.file}${recorded.dropped > 0 ? `, ${recorded.dropped} dropped` : ''}`,
                    ]),
              ].join('\n'),
          );
          if (outcome.failure !== undefined) throw outcome.failure;
        },
      ),
  );
};

/** The options of `hal fleet run` that shape how a mode runs. */
interface ModeOptions {
  timeoutMs: number;
  leader?: string;
  formation: FormationShape;
  spacing: number;
  tolerance: number;
  settleTimeoutMs: number;
}

/** Runs the fleet mode and says how it ended (printed once the recording, if any, is closed). */
async function runMode(
  manager: Awaited<ReturnType<typeof openFleetSession>>['manager'],
  mode: RunMode,
  command: ReturnType<typeof parseCommandSpec>,
  options: ModeOptions,
  ctx: CommandContext,
): Promise<RunOutcome> {
  if (mode === 'synchronized') {
    const report = await runSynchronized(manager, command, options.timeoutMs, ctx.io, ctx.global());
    const failure =
      report.failed.length > 0
        ? new CliError('FAILED', `${command.kind} failed on ${report.failed.join(', ')}`)
        : undefined;
    return {
      value: report,
      text: () => formatReport(`synchronized ${command.kind}`, report),
      ...(failure === undefined ? {} : { failure }),
    };
  }
  const result = await runLeaderFollower(
    manager,
    command,
    {
      leader: options.leader as string,
      formation: options.formation,
      spacing: options.spacing,
      toleranceM: options.tolerance,
      settleTimeoutMs: options.settleTimeoutMs,
    },
    ctx.io,
    ctx.global(),
  );
  const failure = !result.leader.result.success
    ? new CliError('FAILED', `the leader's ${command.kind} failed: ${result.leader.result.code}`)
    : result.formation.reason !== 'leader-stopped'
      ? new CliError('FAILED', `the formation ended: ${result.formation.reason}`)
      : undefined;
  return {
    value: result,
    text: () => formatFormation(result.formation),
    ...(failure === undefined ? {} : { failure }),
  };
}
