import { HalError, normalizeAngle } from '@hal/types';
import type { IMUReading } from '@hal/types';
import type { SimRobot } from './robot/sim-robot.js';
import { SeededRandom } from './rng.js';

/*
 * The simulated IMU: a MEMS gyro and accelerometer as a robot carries them. The gyro measures the
 * body's true turn rate plus a bias (drawn once, when it is first read) and white noise; its
 * heading is that rate integrated from power-on, so it drifts from the true yaw as a real one does
 * and never equals it unless every error is set to zero. Integrating the true rate from power-on
 * gives the true yaw's change, so the heading is the power-on heading plus that change, plus the
 * bias times the time since power-on, plus the noise's random walk (one draw per read, of the
 * spread the time since the last read gives it: the same whatever the reads' spacing). No
 * scale-factor error is modelled.
 */

/** The simulated IMU's errors. Defaults are those of a typical consumer MEMS IMU. */
export interface ImuOptions {
  /**
   * Standard deviation of the gyro's zero-rate bias, degrees per second, drawn once per robot.
   * Default 0.1: what is left after the at-rest calibration a robot makes at power-on (turn-on
   * repeatability and warm-up drift); an uncalibrated consumer MEMS gyro is off by 0.5 to a few
   * degrees per second. 0: a gyro without bias.
   */
  gyroBiasSigmaDegPerS?: number;
  /**
   * The gyro's rate noise density, degrees per second per root hertz. Default 0.01 (consumer MEMS
   * gyros state 0.003 to 0.015): the heading's random walk grows by this times the square root
   * of the seconds gone by, and each rate reading has noise of this times the root of
   * {@link IMU_BANDWIDTH_HZ}.
   */
  gyroNoiseDensity?: number;
  /** Standard deviation of the accelerometer's noise on each reading, m/s^2. Default 0.02. */
  accelNoiseSigma?: number;
  /**
   * Seed of the IMU's errors. Default: drawn from the world's random source when the IMU is first
   * read, so a world with the same seed and the same calls repeats them.
   */
  seed?: number;
}

/** The IMU's bandwidth that sets the noise on each rate reading, hertz. */
export const IMU_BANDWIDTH_HZ = 50;

const DEG = Math.PI / 180;
const G = 9.80665;

/** The options with their defaults; INVALID_PARAMETER naming one that is negative or not finite. */
function resolved(options: ImuOptions): Required<Omit<ImuOptions, 'seed'>> {
  const values = {
    gyroBiasSigmaDegPerS: options.gyroBiasSigmaDegPerS ?? 0.1,
    gyroNoiseDensity: options.gyroNoiseDensity ?? 0.01,
    accelNoiseSigma: options.accelNoiseSigma ?? 0.02,
  };
  for (const [name, value] of Object.entries(values)) {
    if (!Number.isFinite(value) || value < 0) {
      throw new HalError('INVALID_PARAMETER', `"imu.${name}" must be a number >= 0`, {
        details: { field: `imu.${name}` },
      });
    }
  }
  return values;
}

/**
 * One robot's IMU, powered on at construction: its heading starts at the heading the robot
 * reports then (its odometry, which is the start pose's heading on a robot that has not moved).
 */
export class SimulatedImu {
  readonly #options: Required<Omit<ImuOptions, 'seed'>>;
  readonly #seed: (() => number) | number;
  #random: SeededRandom | undefined;
  #biasRadPerS = 0;
  /** Heading at power-on minus the true yaw then: the gyro integrates the change from there. */
  readonly #offsetRad: number;
  readonly #onUs: number;
  #lastUs: number;
  #walkRad = 0;

  /**
   * `seed`: where the errors' seed is drawn when the IMU is first read (the world's random
   * source), unless `options.seed` gives it; an IMU nobody reads draws nothing.
   */
  constructor(robot: SimRobot, options: ImuOptions, seed: () => number) {
    this.#options = resolved(options);
    this.#seed = options.seed ?? seed;
    this.#offsetRad = robot.reportedPose.yaw - robot.yaw;
    this.#onUs = robot.nowUs;
    this.#lastUs = this.#onUs;
  }

  /** The gyro's bias, rad/s (drawn at the first read). */
  get biasRadPerS(): number {
    this.#draws();
    return this.#biasRadPerS;
  }

  #draws(): SeededRandom {
    if (this.#random === undefined) {
      const seed = typeof this.#seed === 'number' ? this.#seed : this.#seed();
      this.#random = new SeededRandom(seed >>> 0);
      this.#biasRadPerS = this.#random.gaussian(this.#options.gyroBiasSigmaDegPerS * DEG);
    }
    return this.#random;
  }

  /**
   * What the IMU reads now: acceleration from the motion (robot frame, gravity +z) and the turn
   * rate, each with noise, and the gyro's integrated heading.
   */
  read(robot: SimRobot): IMUReading {
    const random = this.#draws();
    const o = this.#options;
    const now = robot.nowUs;
    const sinceLast = Math.max(0, now - this.#lastUs) / 1e6;
    this.#lastUs = Math.max(this.#lastUs, now);
    const density = o.gyroNoiseDensity * DEG;
    if (density > 0 && sinceLast > 0)
      this.#walkRad += random.gaussian(density * Math.sqrt(sinceLast));
    const sinceOn = Math.max(0, now - this.#onUs) / 1e6;
    const heading = normalizeAngle(
      robot.yaw + this.#offsetRad + this.#biasRadPerS * sinceOn + this.#walkRad,
    );
    const v = robot.velocity(now);
    const before = robot.velocity(Math.max(0, now - 1000));
    const ax = robot.running ? (v.linear - before.linear) / 0.001 : 0;
    const rateNoise = density * Math.sqrt(IMU_BANDWIDTH_HZ);
    const accel = (value: number) =>
      o.accelNoiseSigma > 0 ? value + random.gaussian(o.accelNoiseSigma) : value;
    return {
      acceleration: { x: accel(ax), y: accel(v.linear * v.angular), z: accel(G) },
      gyroscope: {
        x: rateNoise > 0 ? random.gaussian(rateNoise) : 0,
        y: rateNoise > 0 ? random.gaussian(rateNoise) : 0,
        z: v.angular + this.#biasRadPerS + (rateNoise > 0 ? random.gaussian(rateNoise) : 0),
      },
      heading,
      source: 'simulation',
    };
  }
}
