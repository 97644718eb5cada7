import { GoalSeekingProvider, NavigationBridge, OccupancyGrid } from '@hal/navigation';
import type { DecisionProvider } from '@hal/navigation';
import { ObjectMemory, Perception, perceivingObserver } from '@hal/perception';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { EvalAgent } from '../agent.js';
import { namedObject, namedPoint, ObjectSeekingProvider } from '@hal/skills';

/** Options of {@link cameraNavigationAgent}. */
export interface CameraNavigationAgentOptions {
  /** The name in reports. Default `nav:camera`. */
  name?: string;
  /** Also map with the range sensors where the robot has them. Default false: the camera only. */
  rangeSensors?: boolean;
  /** Side of the square world model, metres, centred on the odometry origin. Default 10. */
  gridM?: number;
  /** Longest leg between two looks, metres (the camera sees the floor to about 2.5 m). Default 1.2. */
  maxLegM?: number;
  /** How much the way the robot first faced is favoured when exploring (see ObjectSeekerOptions). */
  aheadWeight?: number;
  /** Told of each trial's bridge before it runs (to listen to its events: logs, recordings). */
  onBridge?: (bridge: NavigationBridge) => void;
}

/**
 * The navigation bridge seeing only through the camera: it is given the instruction and the
 * robot (no map, no goal point, no ground truth). It reads the named object from the words ("the
 * red box"), and each cycle perception lays the frame's free space into the bridge's grid and
 * remembers the objects it shows; the {@link ObjectSeekingProvider} looks round, explores and
 * approaches the object as the memory places it, and stops before it. An instruction that gives
 * a point in numbers ("x = -0.3 m, y = 0 m") is driven to with the GoalSeekingProvider on the grid
 * the camera maps on the way. Every HAL call goes through the trial's tools, counted and leashed
 * like a model's.
 */
export function cameraNavigationAgent(options: CameraNavigationAgentOptions = {}): EvalAgent {
  return {
    name: options.name ?? 'nav:camera',
    // the words and the robot only: the harness hands it no task, world or true pose
    usesGroundTruth: false,
    run: async (trial) => {
      const hal = trial.hal;
      if (hal === undefined) return { answer: 'No robot to drive.', stopped: 'no robot' };
      const target = namedObject(trial.instruction);
      if (target !== undefined) {
        const memory = new ObjectMemory();
        const provider = new ObjectSeekingProvider({
          target,
          memory,
          ...(options.aheadWeight === undefined ? {} : { aheadWeight: options.aheadWeight }),
        });
        const bridge = cameraBridge(hal, provider, memory, options, 0.15);
        const outcome = await bridge.run(null, { signal: trial.signal });
        const found = provider.found;
        const seen =
          found === undefined
            ? `I did not see the ${target.query}.`
            : `I saw the ${target.query} at (${found.x.toFixed(2)}, ${found.y.toFixed(2)}), ${found.timesSeen} times.`;
        if (provider.phase === 'arrived') {
          return { answer: `Stopped next to the ${target.query}. ${seen}` };
        }
        return {
          answer: `${outcome.message}. ${seen}`,
          stopped: `${provider.phase}: ${outcome.reason}`,
        };
      }
      // A point given in numbers: driven to on the grid the camera maps on the way.
      const point = namedPoint(trial.instruction);
      if (point !== undefined) {
        const tolerance = (point.withinM ?? 0.1) / 2;
        const provider = new GoalSeekingProvider();
        const bridge = cameraBridge(hal, provider, new ObjectMemory(), options, tolerance);
        const outcome = await bridge.run(point, { signal: trial.signal });
        return {
          answer: outcome.message,
          ...(outcome.status === 'reached' ? {} : { stopped: outcome.reason }),
        };
      }
      return {
        answer: 'The instruction names no coloured object and no point to go to.',
        stopped: 'no object named',
      };
    },
  };
}

/** The bridge over `hal` with the camera as its only sense (unless range sensors are asked for). */
function cameraBridge(
  hal: HardwareAbstractionLayer,
  provider: DecisionProvider,
  memory: ObjectMemory,
  options: CameraNavigationAgentOptions,
  goalToleranceM: number,
): NavigationBridge {
  const side = options.gridM ?? 10;
  // a little more room round what the camera saw than the default: a wall's end seen side-on
  // is thin in the image, and the guard stops a leg that passes a corner too near
  const grid = new OccupancyGrid({ widthM: side, heightM: side, clearanceM: 0.08 });
  const perception = new Perception(hal, { grid, memory });
  let frames = 0;
  const bridge = new NavigationBridge({
    hal,
    provider,
    grid,
    // frames are numbered, not timed, so that a trial is repeatable
    observe: perceivingObserver(perception, { now: () => (frames += 1) }),
    rangeSensors: options.rangeSensors === true ? {} : false,
    maxLegM: options.maxLegM ?? 1.2,
    // a leg more than this off the heading is looked at first (the camera sees 62 degrees)
    faceBeforeDrivingDeg: 45,
    goalToleranceM,
    maxCycles: 100,
    // every call is counted: the pose comes with each motion's result
    poseFromResults: true,
  });
  options.onBridge?.(bridge);
  return bridge;
}
