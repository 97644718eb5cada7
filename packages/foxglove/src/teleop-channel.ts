// Teleop as the protocol server receives it: a viewer advertises `/cmd_vel` and publishes Twists
// on it; each becomes one bounded drive through the leashed HAL (teleop.ts). A refusal is said to
// that viewer (a warning status) and in the log; at most a few drives of one viewer are on their
// way at once (more are skipped); a viewer that leaves while its last drive runs has the robot
// stopped at once.
import type { FoxgloveServer, IWebSocket } from '@foxglove/ws-protocol';
import { HalError } from '@hal/types';
import type { HardwareAbstractionLayer, LogLevel, RobotConfig } from '@hal/types';
import { driveOnce, powersOfTwist } from './teleop.js';
import { StatusLevel, bytesOf } from './ws-protocol.js';

/** Teleop messages of one viewer on their way at once, at most; more are skipped. */
const MAX_IN_FLIGHT = 2;

interface Driver {
  name: string;
  /** Joined with `?role=watch`: it sees, stops and e-stops, but does not drive. */
  watchOnly: boolean;
  /** Teleop channels it advertised. */
  channels: Set<number>;
  inFlight: number;
  /** When it last drove, ms (performance.now). */
  droveAt: number | undefined;
}

export interface TeleopOptions {
  /** The topic teleop is published on. */
  topic: string;
  /** The HAL teleop drives: the leashed one. */
  leashed: HardwareAbstractionLayer;
  /** The HAL a stop for a viewer that left goes to: straight to the robot. */
  robot: HardwareAbstractionLayer;
  config: RobotConfig;
  holdMs: number;
  log: (level: LogLevel, message: string) => void;
}

/** Listens for teleop on `server`; `joined` and `left` follow the viewers. */
export function acceptTeleop(
  server: FoxgloveServer,
  options: TeleopOptions,
): {
  joined(connection: IWebSocket, name: string, watchOnly: boolean): void;
  left(connection: IWebSocket): void;
  counts(): { driven: number; refused: number };
} {
  const { topic, leashed, robot, config, holdMs, log } = options;
  const drivers = new Map<IWebSocket, Driver>();
  const counts = { driven: 0, refused: 0 };
  const decoder = new TextDecoder();

  server.on('advertise', (channel) => {
    const driver = drivers.get(channel.client.connection);
    if (driver === undefined || channel.topic !== topic) return;
    if (channel.encoding !== 'json') {
      server.sendStatus(
        {
          level: StatusLevel.ERROR,
          message: `teleop on ${channel.topic} must be published as json, not ${channel.encoding}`,
        },
        channel.client.connection,
      );
      return;
    }
    driver.channels.add(channel.id);
  });
  server.on('unadvertise', ({ client, channelId }) => {
    drivers.get(client.connection)?.channels.delete(channelId);
  });
  server.on('message', ({ client, channel, data }) => {
    const driver = drivers.get(client.connection);
    if (driver === undefined || !driver.channels.has(channel.id)) return;
    const refuse = (code: string, error: string) => {
      counts.refused += 1;
      server.sendStatus(
        { level: StatusLevel.WARNING, message: `teleop refused (${code}): ${error}`, id: 'teleop' },
        client.connection,
      );
      log('warn', `teleop from ${driver.name} refused (${code}): ${error}`);
    };
    if (driver.watchOnly) {
      refuse(
        'NOT_CONTROLLER',
        'this viewer joined with ?role=watch: it may watch and stop, not drive',
      );
      return;
    }
    let powers: { left: number; right: number };
    try {
      powers = powersOfTwist(JSON.parse(decoder.decode(bytesOf(data))), config);
    } catch (error) {
      refuse('INVALID_PARAMETER', error instanceof HalError ? error.message : 'not JSON');
      return;
    }
    if (driver.inFlight >= MAX_IN_FLIGHT) return;
    driver.droveAt = performance.now();
    driver.inFlight += 1;
    void driveOnce(leashed, powers, holdMs).then((outcome) => {
      driver.inFlight -= 1;
      if (outcome.driven) counts.driven += 1;
      else refuse(outcome.code, outcome.error);
    });
  });

  return {
    joined: (connection, name, watchOnly) =>
      drivers.set(connection, {
        name,
        watchOnly,
        channels: new Set(),
        inFlight: 0,
        droveAt: undefined,
      }),
    left(connection) {
      const driver = drivers.get(connection);
      drivers.delete(connection);
      if (driver?.droveAt === undefined || performance.now() - driver.droveAt >= holdMs) return;
      log('warn', `${driver.name} left while driving: stopping the robot`);
      robot.locomotion.stop().then(
        (result) => {
          if (!result.success) log('error', `the stop for ${driver.name} failed: ${result.error}`);
        },
        (error: unknown) => log('error', `the stop for ${driver.name} failed: ${String(error)}`),
      );
    },
    counts: () => ({ ...counts }),
  };
}
