// `hal replay run.mcap`: re-runs a recording's action calls on the simulator (the recorded robot's
// geometry, the recorded map when it is a built-in one) and reports the divergence per call: pose
// and steps; `--svg` plots both trajectories.
import { writeFile } from 'node:fs/promises';
import { Command, Option } from 'commander';
import { replayRecording, trajectorySvg } from '@hal/recorder';
import type { ReplayReport } from '@hal/recorder';
import { BUILTIN_MAPS, SimulationHAL, World } from '@hal/simulation';
import type { BuiltinMapName } from '@hal/simulation';
import type { RobotConfig } from '@hal/types';
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

function reportText(file: string, report: ReplayReport): string {
  const mm = (m: number | undefined) => (m === undefined ? '-' : `${(m * 1000).toFixed(3)} mm`);
  return [
    `replayed ${report.calls.length} calls of ${file} on the simulator`,
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

export const registerReplay: RegisterCommand = (program, { io, global }) => {
  program.addCommand(
    new Command('replay')
      .description("re-run a recording's calls on the simulator and show the divergence per call")
      .argument('<file>', 'an MCAP file written by hal record or @hal/recorder')
      .addOption(new Option('--svg <file>', 'write both trajectories as an SVG plot'))
      .action(async (file: string, options: { svg?: string }) => {
        const recording = await readForCommand(file);
        const robot = recording.metadata.get('hal.robot');
        const config = parsed<RobotConfig | null>(robot?.['robot_config']) ?? undefined;
        const mapName = parsed<{ name?: string } | null>(robot?.['map'])?.name;
        const map =
          mapName !== undefined && mapName in BUILTIN_MAPS ? (mapName as BuiltinMapName) : 'empty';
        const sim = new SimulationHAL({
          world: new World({ map }),
          ...(config ? { robot: config } : {}),
        });
        await sim.initialize();
        let report: ReplayReport;
        try {
          report = await replayRecording(recording, sim);
        } finally {
          await sim.cleanup();
        }
        if (options.svg !== undefined) await writeFile(options.svg, trajectorySvg(report, file));
        emit(io, global(), { file, map, ...report }, () => reportText(file, report));
      }),
  );
};
