import { HALConfigSchema, HalError, robotConfig, V1_ROBOT } from '@hal/types';
import type { HALConfig, RobotConfig } from '@hal/types';
import { serialTransport } from '../transport/serial.js';
import type { TransportFactory } from '../transport/transport.js';
import { udpTransport } from '../transport/udp.js';

/** Checks a PhysicalHAL's config: a valid {@link HALConfig} whose mode is `physical`. */
export function parsePhysicalConfig(config: HALConfig): HALConfig {
  const parsed = HALConfigSchema.safeParse(config);
  if (!parsed.success) {
    const issue = parsed.error.issues[0];
    throw new HalError(
      'INVALID_PARAMETER',
      `PhysicalHAL config: "${issue?.path.join('.') ?? 'config'}" ${issue?.message ?? 'is invalid'}`,
    );
  }
  if (parsed.data.mode !== 'physical') {
    throw new HalError('INVALID_PARAMETER', `PhysicalHAL config: "mode" must be "physical"`);
  }
  return parsed.data;
}

/** The V1 robot with the config's `robot` overrides, until the robot reports its own. */
export function initialRobotConfig(config: HALConfig): RobotConfig {
  const overrides = Object.fromEntries(
    Object.entries(config.robot ?? {}).filter(([, value]) => value !== undefined),
  ) as Partial<RobotConfig>;
  return robotConfig({ ...V1_ROBOT, ...overrides });
}

/** The transport `config.connection` describes: UDP for wifi, the framed serial link for serial. */
export function defaultTransport(config: HALConfig, timeoutMs: number): TransportFactory {
  const connection = config.connection;
  if (connection?.type === 'wifi' && connection.host !== undefined) {
    return udpTransport(
      connection.udpPort === undefined
        ? { host: connection.host }
        : { host: connection.host, port: connection.udpPort },
    );
  }
  if (connection?.type === 'serial' && connection.port !== undefined) {
    // frames are resent as quickly as requests, so a corrupted frame cannot outlast the host timeout
    return serialTransport(
      connection.baudRate === undefined
        ? { path: connection.port, timeoutMs }
        : { path: connection.port, baudRate: connection.baudRate, timeoutMs },
    );
  }
  throw new HalError(
    'INVALID_PARAMETER',
    '"connection" must be { type: "wifi", host } or { type: "serial", port } (or pass a transport)',
    { details: { parameter: 'connection' } },
  );
}
