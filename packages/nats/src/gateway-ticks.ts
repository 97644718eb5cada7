import { toHalError } from '@hal/types';
import { offersStream, readDifferentialState, readImu, readRange } from './gateway-streams.js';
import type { OfferedStreams } from './gateway-streams.js';
import type { GatewayPort } from './gateway-port.js';
import { SCHEMAS } from './messages.js';

/**
 * The gateway's streams, one tick at a time: the differential state, and the IMU and range
 * streams the device offers. A tick still reading when the next is due is not overlapped.
 */
export class StreamTicks {
  #streaming = false;
  #offered: OfferedStreams | undefined;
  #offeredFor = '';

  constructor(readonly port: GatewayPort) {}

  /** One tick of the streams (nothing while closed or while the HAL is not ready). */
  async tick(): Promise<void> {
    const { hal, robot } = this.port;
    if (this.#streaming || this.port.closed || !hal.isReady()) return;
    this.#streaming = true;
    try {
      this.port.publish(
        'differentialState',
        SCHEMAS.differentialState,
        await readDifferentialState(hal, robot),
      );
      const offered = this.#offeredStreams();
      const imu = await readImu(hal, offered.imu);
      if (imu !== undefined) this.port.publish('imuData', SCHEMAS.imu, imu);
      const range = await readRange(hal, offered.range);
      if (range !== undefined) {
        for (const sensor of range.perSensor) this.port.publish('rangeData', SCHEMAS.range, sensor);
        this.port.publish('rangeSummary', SCHEMAS.rangeSummary, range.summary);
      }
    } catch (thrown) {
      this.port.log.debug('state read failed', { error: toHalError(thrown).message });
    } finally {
      this.#streaming = false;
    }
  }

  /**
   * The optional streams the device offers now: its capabilities are read at every tick (a robot
   * may gain a camera or a sensor), but parsed again only when they change.
   */
  #offeredStreams(): OfferedStreams {
    const capabilities = this.port.hal.getDeviceInfo().capabilities;
    const key = capabilities.join('\n');
    if (this.#offered === undefined || this.#offeredFor !== key) {
      this.#offered = offersStream(capabilities);
      this.#offeredFor = key;
    }
    return this.#offered;
  }
}
