import { isHalError } from '@hal/types';
import type { HardwareAbstractionLayer, ScanResult, VisionInterface } from '@hal/types';
import { clearanceAhead } from './clearance.js';
import type { Perception } from './perception.js';

type DetectedObject = ScanResult['objects'][number];

/** What the camera-backed scan keeps clear ahead of the body before it says `clearAhead`. */
const CLEAR_AHEAD_M = 0.3;

/**
 * A scan from what the robot can know: the range sensors' scan where the robot has them, and
 * one look of the camera through perception, each object in the frame of the robot's reported
 * pose (odometry), marked with the sensor that saw it. The camera sees only what is in its view
 * now; its objects carry the memory's ids ("red box 1"), which say what the camera saw, nothing
 * of any task.
 */
export async function scanWithCamera(
  hal: HardwareAbstractionLayer,
  perception: Perception,
  mode: 'full' | 'targeted' | 'quick' = 'quick',
  rangeScan: (mode: 'full' | 'targeted' | 'quick') => Promise<ScanResult> = (m) =>
    hal.vision.scan(m),
): Promise<ScanResult> {
  let range: ScanResult | undefined;
  try {
    range = await rangeScan(mode);
  } catch (error) {
    if (!(isHalError(error) && error.code === 'NOT_IMPLEMENTED')) throw error;
  }
  const look = await perception.look();
  const seen: DetectedObject[] = look.objects.map((object, i) => ({
    id: look.remembered[i]?.id ?? object.label,
    type: object.kind === 'unknown' ? 'object' : object.kind,
    position: { x: object.world.x, y: object.world.y, z: object.heightM / 2 },
    confidence: object.confidence,
    bearingDeg: object.bearingDeg,
    distanceM: object.nearDistanceM,
    sizeM: object.widthM,
    sensor: 'camera',
  }));
  const body = perception.bodyRadiusM;
  const ahead = clearanceAhead(look.freeSpace, body, body + 0.03);
  const cameraClear = !ahead.blocked || ahead.aheadM > CLEAR_AHEAD_M;
  const nearestSeen = look.freeSpace
    .filter((c) => c.hit)
    .reduce(
      (least, c) => Math.min(least, Math.max(0, c.distanceM - body)),
      Number.POSITIVE_INFINITY,
    );
  const nearest = Math.min(range?.nearestObstacle ?? Number.POSITIVE_INFINITY, nearestSeen);
  const result: ScanResult = {
    objects: [
      ...(range?.objects ?? []).map((o) => ({ ...o, sensor: o.sensor ?? ('range' as const) })),
      ...seen,
    ],
    clearAhead: (range?.clearAhead ?? true) && cameraClear,
    frame: 'odometry',
  };
  if (Number.isFinite(nearest)) result.nearestObstacle = nearest;
  return result;
}

/**
 * `hal` with its `vision.scan` answered by {@link scanWithCamera} (range sensors and the camera
 * through `perception`); every other call goes to `hal` as it is.
 */
export function withCameraScan(
  hal: HardwareAbstractionLayer,
  perception: Perception,
): HardwareAbstractionLayer {
  const inner = hal.vision;
  const vision: VisionInterface = {
    captureFrame: () => inner.captureFrame(),
    getDistanceSensors: () => inner.getDistanceSensors(),
    getIMU: () => inner.getIMU(),
    scan: (mode) => scanWithCamera(hal, perception, mode ?? 'quick', (m) => inner.scan(m)),
    getLineSensors: () => inner.getLineSensors(),
  };
  return new Proxy(hal, {
    get(target, property) {
      if (property === 'vision') return vision;
      const value: unknown = Reflect.get(target, property, target);
      return typeof value === 'function'
        ? (value as (...a: unknown[]) => unknown).bind(target)
        : value;
    },
  });
}
