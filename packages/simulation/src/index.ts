export { SimulationHAL } from './hal/simulation-hal.js';
export { WorldBinding } from './hal/world-binding.js';
export type { CommunicationEvent, SimulationHALEvents } from './hal/events.js';
export type {
  FrameSource,
  SimulatedFeatures,
  SimulationClock,
  SimulationHALOptions,
} from './hal/options.js';

export { World } from './world.js';
export type { AddRobotOptions, RealtimeOptions, WorldEvents, WorldOptions } from './world.js';

export { SimRobot } from './robot/sim-robot.js';
export type { LedState, SimRobotOptions } from './robot/sim-robot.js';
export { BodyErrorSchema } from './robot/body-error.js';
export type { BodyError, BodyErrorInput } from './robot/body-error.js';
export type { Contact, ContactTest } from './robot/contact.js';
export type { MotionHandle, MotionReport } from './robot/motion-report.js';
export type { SafetyTrip } from './robot/motion-report.js';

export { WorldMapSchema, parseMap } from './map.js';
export type { WorldMap, WorldMapInput } from './map.js';
export { BUILTIN_MAPS } from './maps/index.js';
export type { BuiltinMapName } from './maps/index.js';

export { castRay, discContact, solidsOf } from './shapes.js';
export type { BoxSolid, CylinderSolid, Point, Rgb, Solid, SolidRole } from './shapes.js';

export { readDistanceSensors, scanAround } from './sensors.js';
export type { RangeSensorOptions } from './sensors.js';
export type { ImuOptions } from './gyro.js';

export { renderRobotView } from './camera.js';
export type { CameraOptions, RgbaImage } from './camera.js';
export { defaultJpegEncoder, encodeJpeg } from './jpeg.js';
export { canvasJpegEncoder, jpegJsEncoder, loadSharpEncoder } from './jpeg-encoders.js';
export type { JpegEncoder } from './jpeg-encoders.js';

export { SeededRandom } from './rng.js';
