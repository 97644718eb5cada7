import { CAPABILITIES, HALConfigSchema, HalError, hasCapability } from '@hal/types';
import type { HALConfig, RobotConfig } from '@hal/types';
import { World } from '../world.js';
import type { SimulatedFeatures, SimulationHALOptions } from './options.js';

/**
 * The SimulationHAL options a shared {@link HALConfig} asks for, over `options`: `mode` must be
 * 'simulation'; `simulator` may be the {@link World} to join; `robot` overrides the V1 geometry
 * and limits; `camera` the camera model it renders with; `deviceId` names the device; and
 * `capabilities`, when given, chooses the simulated features by their capability strings. Throws INVALID_PARAMETER on a bad configuration.
 */
export function optionsFromConfig(
  config: HALConfig,
  options: SimulationHALOptions,
): SimulationHALOptions {
  const parsed = HALConfigSchema.safeParse(config);
  if (!parsed.success) {
    const issue = parsed.error.issues[0];
    const where = issue?.path.map(String).join('.') || 'config';
    throw new HalError('INVALID_PARAMETER', `HALConfig: "${where}" ${issue?.message ?? ''}`, {
      details: { parameter: where },
    });
  }
  const c = parsed.data;
  if (c.mode !== 'simulation') {
    throw new HalError(
      'INVALID_PARAMETER',
      `HALConfig: "mode" must be "simulation" for a SimulationHAL, got "${c.mode}"`,
      { details: { parameter: 'mode' } },
    );
  }
  if (c.simulator !== undefined && !(c.simulator instanceof World)) {
    throw new HalError('INVALID_PARAMETER', 'HALConfig: "simulator" must be a World', {
      details: { parameter: 'simulator' },
    });
  }
  const caps = c.capabilities;
  const features: SimulatedFeatures =
    caps === undefined
      ? (options.features ?? {})
      : {
          camera: hasCapability(caps, CAPABILITIES.camera),
          rangeSensors: hasCapability(caps, CAPABILITIES.rangeSensors),
          imu: hasCapability(caps, CAPABILITIES.imu),
          speaker: hasCapability(caps, CAPABILITIES.speaker),
        };
  return {
    ...options,
    ...(c.simulator instanceof World ? { world: c.simulator } : {}),
    ...(c.robot === undefined
      ? {}
      : {
          robot: Object.fromEntries(
            Object.entries(c.robot).filter(([, v]) => v !== undefined),
          ) as Partial<RobotConfig>,
        }),
    // the camera renders with the config's model (over the options' and V1's)
    ...(c.camera === undefined
      ? {}
      : {
          camera: {
            ...options.camera,
            ...Object.fromEntries(Object.entries(c.camera).filter(([, v]) => v !== undefined)),
          },
        }),
    deviceId: c.deviceId,
    features,
  };
}
