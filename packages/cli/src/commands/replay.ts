// `hal replay run.mcap`: re-runs a recording's action calls on the simulator (the recorded robot's
// geometry, the recorded map when it is a built-in one) and reports the divergence per call: pose
// and steps; `--svg` plots both trajectories. A file cut short or damaged is replayed as far as it
// reads, and the report says where reading stopped; one that is no recording is FAILED.
import { writeFile } from 'node:fs/promises';
import { Command, Option } from 'commander';
import { replayRecording, robotNamespace, summarizeRecording, trajectorySvg } from '@hal/recorder';
import type { Recording, ReplayReport } from '@hal/recorder';
import { BUILTIN_MAPS, SimulationHAL, World } from '@hal/simulation';
import type { BuiltinMapName } from '@hal/simulation';
import type { Pose, RobotConfig } from '@hal/types';
import { CliError } from '../cli-error.js';
import { emit } from '../io.js';
import { readForCommand } from './inspect.js';
import type { RegisterCommand } from './context.js';

function parsed<T>(text: string | undefined): T | undefined {
  try {
    return text === undefined ? undefined : (JSON.parse(text) as T);
  } catch {
    return undefined;
  }
}

function reportText(file: string, report: ReplayReport, truncation: string | undefined): string {
  const mm = (m: number | undefined) => (m === undefined ? '-' : `${(m * 1000).toFixed(3)} mm`);
  return [
    `replayed ${report.calls.length} calls of ${file} on the simulator`,
    ...(truncation === undefined ? [] : [`not read whole: ${truncation}`]),
    ...report.calls.map((c) => {
      const outcome = (o: { success: boolean; code?: string }) =>
        o.success ? 'ok' : (o.code ?? 'failed');
      const same =
        outcome(c.recorded) === outcome(c.replayed)
          ? outcome(c.recorded)
          : `${outcome(c.recorded)} -> ${outcome(c.replayed)}`;
      const steps =
        c.steps === undefined
          ? ''
          : `, steps ${c.steps.recorded.join('/')} vs ${c.steps.replayed.join('/')}`;
      return `  ${c.call}(${c.args.map((a) => JSON.stringify(a)).join(', ')}): ${same}, ${mm(c.positionM)}${steps}`;
    }),
    `max divergence ${mm(report.maxPositionM)}, ${((report.maxYawRad * 180) / Math.PI).toFixed(3)}°; outcomes differing ${report.outcomeMismatches}, steps differing ${report.stepMismatches}`,
  ].join('\n');
}

/** The robot to replay: `--robot` in a recording of several (USAGE without it), else the one. */
function robotOf(
  recording: Recording,
  file: string,
  robot: string | undefined,
): string | undefined {
  const robots = Object.keys(summarizeRecording(recording).robots ?? {});
  if (robot === undefined) {
    if (robots.length > 0 && !recording.channels.has('/hal/calls')) {
      throw new CliError(
        'USAGE',
        `${file} records ${robots.length} robots: name one with --robot (${robots.join(', ')})`,
      );
    }
    return undefined;
  }
  if (!robots.includes(robot)) {
    throw new CliError(
      'USAGE',
      `--robot ${robot}: ${file} has no robot of that name (${robots.join(', ') || 'it records one robot, with no name'})`,
    );
  }
  return robot;
}

/** Where the robot stood when the recording began (its first pose), for the simulator's start. */
function startOf(recording: Recording, topic: string): { x: number; y: number; yaw: number } {
  const first = recording.messages.find((m) => m.topic === topic)?.value as Pose | undefined;
  return first === undefined
    ? { x: 0, y: 0, yaw: 0 }
    : { x: first.position.x, y: first.position.y, yaw: first.rotation.yaw };
}

export const registerReplay: RegisterCommand = (program, { io, global }) => {
  program.addCommand(
    new Command('replay')
      .description("re-run a recording's calls on the simulator and show the divergence per call")
      .argument('<file>', 'an MCAP file written by hal record or @hal/recorder')
      .addOption(new Option('--svg <file>', 'write both trajectories as an SVG plot'))
      .option(
        '--robot <id>',
        'in a recording of several robots (hal fleet run --record), the one to replay',
      )
      .action(async (file: string, options: { svg?: string; robot?: string }) => {
        const recording = await readForCommand(file);
        const namespace = robotOf(recording, file, options.robot);
        const space = robotNamespace(namespace);
        const robot = recording.metadata.get(space.metadataName);
        const config = parsed<RobotConfig | null>(robot?.['robot_config']) ?? undefined;
        const mapName = parsed<{ name?: string } | null>(robot?.['map'])?.name;
        const map =
          mapName !== undefined && mapName in BUILTIN_MAPS ? (mapName as BuiltinMapName) : 'empty';
        const sim = new SimulationHAL({
          world: new World({ map }),
          start: startOf(recording, space.topics.halPose),
          ...(config ? { robot: config } : {}),
        });
        await sim.initialize();
        let report: ReplayReport;
        try {
          report = await replayRecording(
            recording,
            sim,
            namespace === undefined ? {} : { namespace },
          );
        } finally {
          await sim.cleanup();
        }
        if (options.svg !== undefined) await writeFile(options.svg, trajectorySvg(report, file));
        const { truncation } = recording;
        emit(
          io,
          global(),
          {
            file,
            map,
            ...(namespace === undefined ? {} : { robot: namespace }),
            complete: recording.complete,
            ...(truncation === undefined ? {} : { truncation }),
            ...report,
          },
          () => reportText(file, report, truncation),
        );
      }),
  );
};
