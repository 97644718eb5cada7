export { SimulationHAL } from './hal.js';
export type {
  CommunicationEvent,
  FrameSource,
  SimLogger,
  SimulatedFeatures,
  SimulationClock,
  SimulationHALEvents,
  SimulationHALOptions,
} from './hal.js';

export { Emitter, World } from './world.js';
export type { AddRobotOptions, RealtimeOptions, WorldEvents, WorldOptions } from './world.js';

export { SimRobot } from './robot.js';
export type {
  Contact,
  ContactTest,
  LedState,
  MotionHandle,
  MotionReport,
  MoveOutcome,
  SafetyTrip,
  SimRobotOptions,
} from './robot.js';

export {
  BoxObstacleSchema,
  CylinderObstacleSchema,
  ObstacleSchema,
  StartPoseSchema,
  WallSchema,
  WorldMapSchema,
  parseMap,
} from './map.js';
export type { StartPose, WorldMap, WorldMapInput } from './map.js';
export { BUILTIN_MAPS } from './maps/index.js';
export type { BuiltinMapName } from './maps/index.js';

export { castRay, discContact, parseColor, rayEnter, solidsOf } from './shapes.js';
export type { BoxSolid, CylinderSolid, Point, Rgb, Solid, SolidRole } from './shapes.js';

export { rangeAlong, readDistanceSensors, readImu, scanAround } from './sensors.js';
export type { RangeSensorOptions } from './sensors.js';

export { cameraPose, renderRobotView } from './camera.js';
export type { CameraOptions, RgbaImage } from './camera.js';
export { encodeJpeg, jpegDataUrl, toBase64 } from './jpeg.js';

export { SeededRandom } from './rng.js';
