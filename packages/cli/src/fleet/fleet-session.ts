// Opens what every `hal fleet` subcommand needs: a NATS connection, the device list (given with
// --device, or heard in the devices' capability announcements) and a started DeviceManager.
import { DeviceManager, discoverNatsDevices } from '@hal/fleet/node';
import type { DiscoveredDevice } from '@hal/fleet/node';
import { openConnection } from '@hal/nats';
import { CliError } from '../cli-error.js';
import { progress } from '../io.js';
import type { CliIO, GlobalOptions } from '../io.js';
import { natsConnectOptions } from '../nats-options.js';
import type { NatsCliOptions } from '../nats-options.js';

/** Options every `hal fleet` subcommand takes. */
export interface FleetCliOptions extends NatsCliOptions {
  device?: string[];
  discoverMs: number;
  offlineAfterMs: number;
}

export interface FleetSession {
  manager: DeviceManager;
  /** The announcements heard (empty when the devices were given). */
  discovered: DiscoveredDevice[];
  close(): Promise<void>;
}

/** Connects, finds the devices and starts a manager over them; the caller closes it. */
export async function openFleetSession(
  options: FleetCliOptions,
  io: CliIO,
  global: GlobalOptions,
): Promise<FleetSession> {
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
        offlineAfterMs: options.offlineAfterMs,
      },
      { natsConnection: { connection } },
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
