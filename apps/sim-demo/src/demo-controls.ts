import { BUILTIN_MAPS } from '@hal/simulation';
import type { BuiltinMapName, SimulationHAL } from '@hal/simulation';
import { element } from './dom.js';
import type { GoalDriver } from './goal-driver.js';
import type { KeyboardTeleop } from './keyboard-teleop.js';
import type { TrajectoryPlot } from './plot.js';
import type { ResultsLog } from './results-log.js';
import type { StatusLine } from './status-line.js';
import { MAP_NAMES } from './url-settings.js';
import type { Viewport } from './viewport.js';

export interface DemoControlsOptions {
  hal: SimulationHAL;
  goals: GoalDriver;
  teleop: KeyboardTeleop;
  viewport: Viewport;
  plot: TrajectoryPlot;
  log: ResultsLog;
  status: StatusLine;
  /** Loads a map, putting every robot at a start again. */
  setMap: (name: BuiltinMapName) => void;
  /** The map shown first. */
  mapName: BuiltinMapName;
  /** The simulation speed the ticker runs at first. */
  speed: number;
  /** "Plan around obstacles" and "Grid" (the goal driver reads them too). */
  planToggle: HTMLInputElement;
  gridToggle: HTMLInputElement;
}

/**
 * The page's controls: map and speed menus, Reset, the planning and grid toggles, the LED colour,
 * "Follow robot", "Simulate a silent host", and the E-STOP button (or Escape), which latches the
 * emergency stop and, once latched, resets it. A control gives the keyboard back once used.
 */
export class DemoControls {
  readonly #options: DemoControlsOptions;
  readonly #silentToggle = element<HTMLInputElement>('silent-toggle');
  readonly #followToggle = element<HTMLInputElement>('follow-toggle');
  #mapName: BuiltinMapName;

  constructor(options: DemoControlsOptions) {
    this.#options = options;
    this.#mapName = options.mapName;
    const { hal, goals, viewport, log, planToggle, gridToggle } = options;

    element<HTMLButtonElement>('estop-button').addEventListener(
      'click',
      () => void this.emergencyStop(),
    );
    window.addEventListener('keydown', (e) => {
      if (e.target instanceof HTMLSelectElement) return;
      if (e.key === 'Escape') void this.emergencyStop();
    });

    const mapSelect = element<HTMLSelectElement>('map-select');
    for (const name of MAP_NAMES) {
      const option = document.createElement('option');
      option.value = name;
      option.textContent = name[0]?.toUpperCase() + name.slice(1);
      mapSelect.append(option);
    }
    mapSelect.value = this.#mapName;
    mapSelect.addEventListener('change', () => {
      void this.resetWorld(mapSelect.value as BuiltinMapName);
      mapSelect.blur();
    });
    element<HTMLButtonElement>('reset-button').addEventListener(
      'click',
      () => void this.resetWorld(this.#mapName),
    );

    const speedSelect = element<HTMLSelectElement>('speed-select');
    speedSelect.value = String(options.speed);
    speedSelect.addEventListener('change', () => {
      hal.world.startRealtime({ speed: Number(speedSelect.value) });
      speedSelect.blur();
    });

    planToggle.addEventListener('change', () => planToggle.blur());
    gridToggle.addEventListener('change', () => {
      gridToggle.blur();
      goals.showGrid();
    });

    const silentToggle = this.#silentToggle;
    silentToggle.addEventListener('change', () => {
      silentToggle.blur();
      hal.simulateHostSilence(silentToggle.checked);
      log.note(
        silentToggle.checked
          ? `host silent: a motion stops ${hal.robot.config.hostTimeoutMs} ms after the last command`
          : 'host talking again',
      );
    });

    const followToggle = this.#followToggle;
    followToggle.addEventListener('change', () => {
      followToggle.blur();
      viewport.follow(followToggle.checked);
    });

    const ledInput = element<HTMLInputElement>('led-input');
    ledInput.addEventListener('change', async () => {
      const hex = Number.parseInt(ledInput.value.slice(1), 16);
      const [r, g, b] = [(hex >> 16) & 255, (hex >> 8) & 255, hex & 255];
      log.record(`setLED(${r}, ${g}, ${b})`, await hal.communication.setLED(r, g, b, 'solid'));
      ledInput.blur();
    });
  }

  /** Latches the emergency stop (cancelling any goal), or resets it when latched. */
  async emergencyStop(): Promise<void> {
    const { hal, goals, teleop, log, status } = this.#options;
    teleop.releaseKeys();
    if (hal.safety.isEmergencyStopped()) {
      log.record('resetEmergencyStop()', await hal.safety.resetEmergencyStop());
      status.set('Emergency stop cleared');
    } else {
      log.record('emergencyStop()', await hal.safety.emergencyStop('stop button in the demo'));
      status.set('EMERGENCY STOP latched: motion is refused until you reset it', 'bad');
      await goals.cancel();
    }
    teleop.forgetLastDrive();
  }

  /** Loads map `name` and puts the robots back at their starts (Reset: the same map again). */
  async resetWorld(name: BuiltinMapName): Promise<void> {
    const { hal, goals, teleop, viewport, plot, status, setMap } = this.#options;
    await goals.cancel();
    teleop.releaseKeys();
    teleop.forgetLastDrive();
    this.#mapName = name;
    setMap(name);
    hal.simulateHostSilence(this.#silentToggle.checked);
    goals.startOver();
    plot.clear();
    viewport.follow(this.#followToggle.checked);
    status.set(`Map "${name}": ${BUILTIN_MAPS[name].description}`);
  }
}
