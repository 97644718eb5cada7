// Where `hal eval` runs its agents: `--on sim,emulator,udp://HOST:PORT`. The simulator scores from
// its ground truth; a robot (the cube-emulator this command starts, or any robot over UDP) runs
// the tasks judged from what it reports, through PhysicalHAL, one session per trial; the emulator
// this command starts is put into each task's world (staged-emulator.ts) and runs every task.
import type { EvalRobot } from '@hal/eval';
import { PhysicalHAL } from '@hal/physical';
import { z } from 'zod';
import { CliError } from '../cli-error.js';
import { WHEEL_REPORT_MS } from '../emulate/emulate-options.js';
import { startEmulatorProcess, WheelsEventSchema } from '../emulate/emulator-process.js';
import type { EmulatorProcess } from '../emulate/emulator-process.js';
import { locateEmulator } from '../emulate/locate-emulator.js';
import { DEFAULT_CONNECT_TIMEOUT_MS } from '../target.js';
import { hostPortArg } from '../values.js';
import { stagedEmulator } from './staged-emulator.js';
import type { EmulatorWheels } from './staged-emulator.js';

/** One place of `--on`. */
export type EvalPlace =
  { kind: 'sim' } | { kind: 'emulator' } | { kind: 'udp'; host: string; port: number };

const PLACES = 'sim, emulator, udp://HOST[:PORT]';

/** Parses `--on sim,emulator,udp://127.0.0.1:4210` (each place once). */
export function parsePlaces(text: string): EvalPlace[] {
  const names = text
    .split(',')
    .map((p) => p.trim())
    .filter((p) => p !== '');
  if (names.length === 0) throw new CliError('USAGE', `"--on" names no place (${PLACES})`);
  if (new Set(names).size !== names.length)
    throw new CliError('USAGE', '"--on" names a place twice');
  return names.map((name): EvalPlace => {
    if (name === 'sim') return { kind: 'sim' };
    if (name === 'emulator') return { kind: 'emulator' };
    if (name.startsWith('udp://')) {
      try {
        return { kind: 'udp', ...hostPortArg('--on')(name.slice('udp://'.length)) };
      } catch (error) {
        throw new CliError('USAGE', (error as Error).message);
      }
    }
    throw new CliError('USAGE', `"--on": unknown place "${name}" (${PLACES})`);
  });
}

/** The robots of `--on`, ready to score on, and what to stop when the run is over. */
export interface EvalRobots {
  simulator: boolean;
  robots: EvalRobot[];
  dispose(): Promise<void>;
}

export interface EvalRobotOptions {
  /** The robot's clock speed-up: the emulator is started with it; a UDP robot runs at it. */
  timeScale?: number;
  /** A UDP robot's pre-shared key. */
  key?: string;
  env: Readonly<Record<string, string | undefined>>;
  signal: AbortSignal;
  /** Told before the emulator is located or built. */
  onBuild?: (dir: string) => void;
}

function udpRobot(
  name: string,
  host: string,
  port: number,
  timeScale: number,
  key: string | undefined,
): EvalRobot {
  return {
    name,
    timeScale,
    open: () =>
      Promise.resolve(
        new PhysicalHAL(
          {
            mode: 'physical',
            deviceId: 'robot',
            connection: {
              type: 'wifi',
              host,
              udpPort: port,
              ...(key === undefined ? {} : { key }),
            },
          },
          { timeScale, client: 'hal-eval', connectTimeoutMs: DEFAULT_CONNECT_TIMEOUT_MS },
        ),
      ),
  };
}

/** The firmware's host timeout: its default and its largest, ms. */
const HOST_TIMEOUT = { default: 2000, max: 10_000 } as const;

/**
 * The host timeout of the emulator `hal eval` starts, its own ms: the firmware's 2 s of real time
 * as far as its limit of 10 s allows. The timeout guards a real-time link; a clock sped up N times
 * would leave the host 2/N s (200 ms at 10x) to be heard, which a loaded machine misses, and the
 * emulator then stops a motion that a robot at 1x would finish.
 */
export function emulatorHostTimeoutMs(timeScale: number): number {
  return Math.min(HOST_TIMEOUT.max, Math.max(HOST_TIMEOUT.default, Math.round(2000 * timeScale)));
}

/** The wheel positions in the emulator's `move_finished` event. */
const MoveFinishedPositionsSchema = z.object({
  event: z.literal('move_finished'),
  left_position: z.number().int(),
  right_position: z.number().int(),
});

/** The wheels an emulator tells in its `wheels` events, and the handler of its events. */
function wheelsTold(): { wheels: EmulatorWheels; told: (event: Record<string, unknown>) => void } {
  let now = { left: 0, right: 0 };
  let at = performance.now();
  const listeners = new Set<() => void>();
  return {
    wheels: {
      now: () => now,
      lastReportAt: () => at,
      onReport: (listener) => {
        listeners.add(listener);
        return () => listeners.delete(listener);
      },
    },
    told: (event) => {
      // a finished motion tells where the wheels stopped at once; a wheels report comes later
      const wheels = WheelsEventSchema.or(MoveFinishedPositionsSchema).safeParse(event);
      if (!wheels.success) return;
      now = { left: wheels.data.left_position, right: wheels.data.right_position };
      at = performance.now();
      for (const listener of listeners) listener();
    },
  };
}

/** Starts what `places` need (the emulator) and describes the robots. */
export async function openPlaces(
  places: readonly EvalPlace[],
  options: EvalRobotOptions,
): Promise<EvalRobots> {
  const timeScale = options.timeScale ?? 1;
  let emulator: EmulatorProcess | undefined;
  const robots: EvalRobot[] = [];
  try {
    for (const place of places) {
      if (place.kind === 'udp') {
        robots.push(
          udpRobot(
            `udp:${place.host}:${place.port}`,
            place.host,
            place.port,
            timeScale,
            options.key,
          ),
        );
      } else if (place.kind === 'emulator') {
        const path = await locateEmulator({
          env: options.env,
          signal: options.signal,
          ...(options.onBuild === undefined ? {} : { onBuild: options.onBuild }),
        });
        const args = ['--udp-port', '0', '--bind', '127.0.0.1', '--device-id', 'cube-emulator'];
        args.push('--no-pty', '--time-scale', String(timeScale));
        args.push('--report-wheels-ms', String(WHEEL_REPORT_MS));
        args.push('--host-timeout-ms', String(emulatorHostTimeoutMs(timeScale)));
        const wheels = wheelsTold();
        emulator = await startEmulatorProcess(path, args, wheels.told);
        robots.push(stagedEmulator(emulator.ready.udp_port, timeScale, wheels.wheels));
      }
    }
  } catch (error) {
    await emulator?.stop();
    throw error;
  }
  const running = emulator;
  return {
    simulator: places.some((p) => p.kind === 'sim'),
    robots,
    dispose: async () => {
      await running?.stop();
    },
  };
}
