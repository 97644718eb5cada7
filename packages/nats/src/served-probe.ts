// Whether a device id, or the default device, is already served on a NATS: two gateways on the
// same subjects would both execute every command and both answer it.
import { HalError } from '@hal/types';
import type { NatsConnection } from '@nats-io/transport-node';
import { encodeMessage } from './codec.js';
import { SCHEMAS } from './messages.js';
import { subjectFor } from './subjects.js';

/** How long a gateway already serving the device has to answer the probe, ms. */
const PROBE_TIMEOUT_MS = 1000;

/** Whether something answers a health request on `subject` (NATS says "no responders" if not). */
async function answers(nc: NatsConnection, subject: string, from: string): Promise<boolean> {
  const body = encodeMessage(SCHEMAS.healthRequest, from, [], {});
  try {
    await nc.request(subject, body, { timeout: PROBE_TIMEOUT_MS });
    return true;
  } catch {
    // no responders: nobody serves it; a timeout: a subscriber that does not answer health,
    // which is not a gateway
    return false;
  }
}

/** What to check: a device id (when known yet) and whether the default device is wanted. */
export interface ServedProbe {
  deviceId?: string;
  defaultDevice: boolean;
}

/**
 * Refuses (INVALID_PARAMETER, naming the subject that answered) a device id that a gateway on
 * `nc` already serves, and the default device when another gateway is it. It asks each
 * `system.health.req`: a request nobody subscribes to fails at once ("no responders").
 */
export async function refuseServedTwice(nc: NatsConnection, probe: ServedProbe): Promise<void> {
  const from = `hal-gateway-probe-${probe.deviceId ?? 'default'}`;
  if (probe.deviceId !== undefined) {
    const own = subjectFor('health', probe.deviceId);
    if (await answers(nc, own, from)) {
      throw new HalError(
        'INVALID_PARAMETER',
        `device "${probe.deviceId}" is already served on this NATS (a gateway answers ${own}): stop that one, or serve this robot under another device id`,
        { details: { parameter: 'deviceId', deviceId: probe.deviceId, subject: own } },
      );
    }
  }
  if (probe.defaultDevice) {
    const bare = subjectFor('health');
    if (await answers(nc, bare, from)) {
      throw new HalError(
        'INVALID_PARAMETER',
        `another gateway already serves the default device on this NATS (it answers ${bare}): serve this one with defaultDevice: false (hal serve --no-default-device)`,
        { details: { parameter: 'defaultDevice', subject: bare } },
      );
    }
  }
}
