// Node only: the device manager routes devices to NatsHAL and to the builders it is given.
export { DeviceManager } from './device-manager.js';
export type { DeviceManagerOptions } from './device-manager.js';
export { createDeviceHAL } from './create-device-hal.js';
export type { DeviceFactories, DeviceHALContext } from './create-device-hal.js';
export {
  DeviceConfigSchema,
  FleetConfigSchema,
  PhysicalDeviceSchema,
  SimulatedDeviceSchema,
  parseFleetConfig,
} from './device-config.js';
export type {
  DeviceConfig,
  FleetConfig,
  FleetConfigInput,
  PhysicalDeviceConfig,
  SimulatedDeviceConfig,
} from './device-config.js';
export type { DeviceHealth, DeviceManagerEvents, DeviceTelemetry } from './device-status.js';
export { discoverNatsDevices } from './discover.js';
export type { DiscoveredDevice } from './discover.js';
