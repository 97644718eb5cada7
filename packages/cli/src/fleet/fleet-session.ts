// Opens what every `hal fleet` subcommand needs: the device list (from --config, given with
// --device, or heard in the devices' capability announcements on NATS) and a started
// DeviceManager over it. NATS is opened only when a device is on NATS.
import { DeviceManager, discoverNatsDevices } from '@hal/fleet/node';
import type { DiscoveredDevice, FleetConfig } from '@hal/fleet/node';
import type { DeviceManagerOptions } from '@hal/fleet/node';
import { openConnection } from '@hal/nats';
import { CliError } from '../cli-error.js';
import { readFleetConfigFile, selectDevices } from './fleet-config-file.js';
import { progress } from '../io.js';
import type { CliIO, GlobalOptions } from '../io.js';
import { natsConnectOptions } from '../nats-options.js';
import type { NatsCliOptions } from '../nats-options.js';
import { deviceFactories } from './device-factories.js';

/** Options every `hal fleet` subcommand takes. */
export interface FleetCliOptions extends NatsCliOptions {
  device?: string[];
  /** A fleet config file (JSON): its devices instead of NATS discovery. */
  config?: string;
  discoverMs: number;
  /** Overrides the config file's; default 3000. */
  offlineAfterMs?: number;
}

const DEFAULT_OFFLINE_AFTER_MS = 3000;

export interface FleetSession {
  manager: DeviceManager;
  /** The announcements heard (empty when the devices were given). */
  discovered: DiscoveredDevice[];
  close(): Promise<void>;
}

/** What a subcommand adds to the device manager (a recorder's `wrapDevice`). */
export type FleetSessionExtras = Pick<DeviceManagerOptions, 'wrapDevice'>;

/** Connects, finds the devices and starts a manager over them; the caller closes it. */
export async function openFleetSession(
  options: FleetCliOptions,
  io: CliIO,
  global: GlobalOptions,
  extras: FleetSessionExtras = {},
): Promise<FleetSession> {
  if (options.config !== undefined)
    return openConfiguredSession(options.config, options, io, global, extras);
  const connection = await openConnection(natsConnectOptions(options, io.env, 'hal-fleet'));
  try {
    let ids = options.device ?? [];
    let discovered: DiscoveredDevice[] = [];
    if (ids.length === 0) {
      progress(io, global, `listening ${options.discoverMs} ms for device announcements...`);
      discovered = await discoverNatsDevices(connection, options.discoverMs);
      ids = discovered.map((d) => d.device);
      if (ids.length === 0) {
        throw new CliError(
          'NOT_FOUND',
          `no device announced itself on NATS within ${options.discoverMs} ms (give --device, or a longer --discover-ms)`,
        );
      }
    }
    const manager = new DeviceManager(
      {
        devices: ids.map((id) => ({ type: 'nats', id })),
        telemetryRateHz: 1,
        offlineAfterMs: options.offlineAfterMs ?? DEFAULT_OFFLINE_AFTER_MS,
      },
      { natsConnection: { connection }, ...extras },
    );
    progress(io, global, `connecting to ${ids.length} device(s)...`);
    await manager.start();
    return {
      manager,
      discovered,
      close: async () => {
        await manager.stop();
        await connection.close();
      },
    };
  } catch (error) {
    await connection.close();
    throw error;
  }
}

/**
 * The session of `--config <file>`: the file's devices (narrowed by --device). NATS is reached
 * through the file's `nats` section, else through the --nats options, and only when a device is
 * of type "nats"; simulated and physical devices need no NATS at all.
 */
async function openConfiguredSession(
  path: string,
  options: FleetCliOptions,
  io: CliIO,
  global: GlobalOptions,
  extras: FleetSessionExtras,
): Promise<FleetSession> {
  const file = await readFleetConfigFile(path);
  const config: FleetConfig = {
    ...selectDevices(file, options.device ?? []),
    ...(options.offlineAfterMs === undefined ? {} : { offlineAfterMs: options.offlineAfterMs }),
  };
  if (config.devices.length === 0) {
    throw new CliError('NOT_FOUND', `--config ${path}: the file lists no devices`);
  }
  const needsCliNats = config.nats === undefined && config.devices.some((d) => d.type === 'nats');
  const connection = needsCliNats
    ? await openConnection(natsConnectOptions(options, io.env, 'hal-fleet'))
    : undefined;
  try {
    const manager = new DeviceManager(config, {
      devices: deviceFactories(io.env),
      ...extras,
      ...(connection === undefined ? {} : { natsConnection: { connection } }),
    });
    progress(io, global, `connecting to ${config.devices.length} device(s)...`);
    await manager.start();
    return {
      manager,
      discovered: [],
      close: async () => {
        await manager.stop();
        await connection?.close();
      },
    };
  } catch (error) {
    await connection?.close();
    throw error;
  }
}
