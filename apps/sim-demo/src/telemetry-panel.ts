import { readDistanceSensors } from '@hal/simulation';
import type { SimRobot, World } from '@hal/simulation';

export interface TelemetryPanelElements {
  /** The list the rows go in. */
  list: HTMLElement;
  /** SAFE / MOVING / E-STOP LATCHED. */
  badge: HTMLElement;
  /** Reads E-STOP, or RESET E-STOP while the e-stop is latched. */
  estopButton: HTMLButtonElement;
}

/**
 * Live telemetry: simulated time, pose, speed, step counts, wheel speeds, the motion and its
 * outcome, range readings, LED and the last safety trip, with a safety badge.
 */
export class TelemetryPanel {
  readonly #elements: TelemetryPanelElements;
  readonly #rows = new Map<string, HTMLElement>();

  constructor(elements: TelemetryPanelElements) {
    this.#elements = elements;
  }

  /** Shows the robot's state now. */
  show(world: World, robot: SimRobot): void {
    const v = robot.velocity();
    const wheels = robot.wheelSpeeds();
    const motion = robot.motion;
    const ranges = readDistanceSensors(world, robot);
    this.#row('Sim time', `${(world.nowUs / 1e6).toFixed(1)} s`);
    this.#row('Position', `x ${robot.x.toFixed(3)} m, y ${robot.y.toFixed(3)} m`);
    this.#row('Heading', `${((robot.yaw * 180) / Math.PI).toFixed(1)}°`);
    this.#row(
      'Speed',
      `${(v.linear * 100).toFixed(2)} cm/s, ${((v.angular * 180) / Math.PI).toFixed(1)}°/s`,
    );
    this.#row('Wheel steps', `L ${robot.leftSteps}, R ${robot.rightSteps}`);
    this.#row('Wheel speed', `L ${Math.round(wheels.left)}, R ${Math.round(wheels.right)} steps/s`);
    this.#row(
      'Motion',
      motion === undefined ? '–' : `#${motion.moveId} ${motion.kind}: ${motion.outcome}`,
    );
    this.#row(
      'Range F/L/R',
      `${ranges.front.toFixed(2)} / ${ranges.left.toFixed(2)} / ${ranges.right.toFixed(2)} m`,
    );
    const led = robot.led;
    this.#row(
      'LED',
      led.pattern === 'off' ? 'off' : `rgb(${led.r}, ${led.g}, ${led.b}) ${led.pattern}`,
    );
    const trip = robot.lastTrip;
    this.#row(
      'Last trip',
      trip === undefined ? 'none' : `${trip.reason} at ${(trip.atUs / 1e6).toFixed(1)} s`,
    );
    const { badge, estopButton } = this.#elements;
    if (robot.emergencyStopped) {
      badge.textContent = 'E-STOP LATCHED';
      badge.className = 'badge bad';
      estopButton.textContent = 'RESET E-STOP';
      estopButton.classList.add('latched');
    } else {
      const moving = motion?.outcome === 'running';
      badge.textContent = moving ? 'MOVING' : 'SAFE';
      badge.className = `badge ${moving ? 'warn' : 'ok'}`;
      estopButton.textContent = 'E-STOP';
      estopButton.classList.remove('latched');
    }
  }

  #row(label: string, value: string): void {
    let dd = this.#rows.get(label);
    if (dd === undefined) {
      const dt = document.createElement('dt');
      dt.textContent = label;
      dd = document.createElement('dd');
      this.#elements.list.append(dt, dd);
      this.#rows.set(label, dd);
    }
    if (dd.textContent !== value) dd.textContent = value;
  }
}
