import { HybridHAL } from '@hal/hybrid';
import type { DivergenceEvent } from '@hal/hybrid';
import { RemoteHAL } from '@hal/remote';
import { invokeSpec, motionCall, errorMessage } from '@hal/types';
import type { HALToolResult, HardwareAbstractionLayer, Pose } from '@hal/types';
import { make } from './dom.js';
import type { ResultsLog } from './results-log.js';

/*
 * The "Remote robot" card: connects to a HAL served over WebSocket (e.g. `hal serve --udp ... --ws-port 8765` in
 * front of the robot or its emulator), and drives it through a HybridHAL whose twin is this page's
 * simulated robot, so the twin moves beside the remote robot and their divergence is shown.
 */

/** What the card shows, for the end-to-end test. */
export interface RemoteState {
  connection: 'off' | 'connecting' | 'connected' | 'failed';
  role: string;
  pose: { x: number; y: number; yaw: number } | null;
  divergence: { positionM: number; yawRad: number; exceeded: boolean } | null;
  lastResult: { call: string; success: boolean; code?: string } | null;
}

/** The HAL's straight drive that way, 10 cm. */
const tenCm = (motion: 'forward' | 'backward') => (hal: HardwareAbstractionLayer) =>
  invokeSpec(hal, motionCall(motion), [10]) as Promise<HALToolResult>;

const ACTIONS: Array<[string, string, (hal: HardwareAbstractionLayer) => Promise<HALToolResult>]> =
  [
    ['forward', 'Forward 10 cm', tenCm('forward')],
    ['back', 'Back 10 cm', tenCm('backward')],
    ['left', 'Left 90°', (hal) => hal.locomotion.rotate('left', 90)],
    ['right', 'Right 90°', (hal) => hal.locomotion.rotate('right', 90)],
    ['stop', 'Stop', (hal) => hal.locomotion.stop()],
    ['estop', 'E-stop', (hal) => hal.safety.emergencyStop('remote panel')],
    ['reset', 'Reset e-stop', (hal) => hal.safety.resetEmergencyStop()],
  ];

export class RemotePanel {
  readonly state: RemoteState = {
    connection: 'off',
    role: '-',
    pose: null,
    divergence: null,
    lastResult: null,
  };
  readonly #twin: HardwareAbstractionLayer;
  readonly #log: ResultsLog;
  readonly #badge = make('span', { className: 'badge', textContent: 'OFF', id: 'remote-badge' });
  readonly #url = make('input', {
    id: 'remote-url',
    value: 'ws://127.0.0.1:8765',
    ariaLabel: 'Remote HAL URL',
  });
  readonly #token = make('input', {
    id: 'remote-token',
    type: 'password',
    placeholder: 'token (if the server has one)',
    autocomplete: 'off',
    ariaLabel: 'Remote HAL token',
  });
  readonly #connect = make('button', {
    id: 'remote-connect',
    type: 'submit',
    textContent: 'Connect',
  });
  readonly #info = make('dl', { className: 'telemetry', id: 'remote-info' });
  readonly #buttons: HTMLButtonElement[] = [];
  #remote: RemoteHAL | undefined;
  #hybrid: HybridHAL | undefined;
  #poll: ReturnType<typeof setInterval> | undefined;

  constructor(card: HTMLElement, twin: HardwareAbstractionLayer, log: ResultsLog) {
    this.#twin = twin;
    this.#log = log;
    const form = make('form', { className: 'remote-form' }, this.#url, this.#token, this.#connect);
    form.addEventListener('submit', (e) => {
      e.preventDefault();
      void (this.#remote === undefined ? this.connect() : this.disconnect());
    });
    const actions = make('div', { className: 'remote-actions' });
    for (const [id, label, run] of ACTIONS) {
      const button = make('button', {
        className: id === 'estop' ? 'estop' : 'secondary',
        textContent: label,
        disabled: true,
      });
      button.dataset['remote'] = id;
      button.addEventListener('click', () => void this.#run(id, run));
      this.#buttons.push(button);
      actions.append(button);
    }
    card.append(make('h2', {}, 'Remote robot ', this.#badge), form, actions, this.#info);
    this.#render();
  }

  async connect(): Promise<void> {
    const token = this.#token.value.trim();
    const remote = new RemoteHAL({
      url: this.#url.value.trim(),
      ...(token === '' ? {} : { token }),
      control: 'take',
      reconnect: false,
    });
    this.state.connection = 'connecting';
    this.#render();
    const hybrid = new HybridHAL({ physical: remote, twin: this.#twin });
    // Every call's result carries the divergence; this also reports a measurement beyond tolerance.
    hybrid.onDivergence((event: DivergenceEvent) => {
      this.state.divergence = { ...event.divergence };
      this.#render();
    });
    try {
      // The remote side first: a HybridHAL that fails to open cleans up both sides, and the twin
      // is this page's robot.
      await remote.initialize();
      await hybrid.initialize();
    } catch (e) {
      await remote.cleanup();
      this.state.connection = 'failed';
      this.#log.note(`Remote robot: ${errorMessage(e)}`);
      this.#render();
      return;
    }
    this.#remote = remote;
    this.#hybrid = hybrid;
    this.state.connection = 'connected';
    this.#poll = setInterval(() => void this.#refresh(), 250);
    this.#log.note(`Remote robot: connected to ${remote.getDeviceInfo().id} (${remote.mode})`);
    await this.#refresh();
  }

  async disconnect(): Promise<void> {
    clearInterval(this.#poll);
    // Only the remote side is released: the twin is this page's robot and keeps running.
    await this.#remote?.cleanup();
    this.#remote = undefined;
    this.#hybrid = undefined;
    this.state.connection = 'off';
    this.state.role = '-';
    this.#render();
  }

  async #run(
    id: string,
    run: (hal: HardwareAbstractionLayer) => Promise<HALToolResult>,
  ): Promise<void> {
    const hal = this.#hybrid;
    if (hal === undefined) return;
    const result = await run(hal);
    this.state.lastResult = {
      call: id,
      success: result.success,
      ...(result.code === undefined ? {} : { code: result.code }),
    };
    const divergence = result.data?.['divergence'] as RemoteState['divergence'] | undefined;
    if (divergence !== undefined) this.state.divergence = divergence;
    this.#log.record(`remote ${id}`, result);
    await this.#refresh();
  }

  async #refresh(): Promise<void> {
    const remote = this.#remote;
    if (remote === undefined) return;
    if (!remote.isReady()) {
      this.state.connection = 'failed';
      this.#log.note('Remote robot: connection lost');
      await this.disconnect();
      this.state.connection = 'failed';
      this.#render();
      return;
    }
    this.state.role = remote.role;
    const pose: Pose | undefined = await remote.locomotion.getPose().catch(() => undefined);
    if (pose !== undefined) {
      this.state.pose = { x: pose.position.x, y: pose.position.y, yaw: pose.rotation.yaw };
    }
    this.#render();
  }

  #render(): void {
    const { connection, role, pose, divergence } = this.state;
    const stopped = this.#remote?.safety.isEmergencyStopped() ?? false;
    this.#badge.textContent = stopped ? 'E-STOP' : connection.toUpperCase();
    this.#badge.className = `badge ${stopped || connection === 'failed' ? 'bad' : connection === 'connected' ? 'ok' : 'warn'}`;
    this.#connect.textContent = this.#remote === undefined ? 'Connect' : 'Disconnect';
    for (const button of this.#buttons) button.disabled = connection !== 'connected';
    const rows: Array<[string, string]> = [
      ['Role', role],
      [
        'Remote pose',
        pose === null
          ? '-'
          : `x ${pose.x.toFixed(3)} m, y ${pose.y.toFixed(3)} m, yaw ${((pose.yaw * 180) / Math.PI).toFixed(1)}°`,
      ],
      [
        'Twin divergence',
        divergence === null
          ? '-'
          : `${(divergence.positionM * 1000).toFixed(1)} mm, ${((divergence.yawRad * 180) / Math.PI).toFixed(2)}°${divergence.exceeded ? ' (exceeded)' : ''}`,
      ],
    ];
    this.#info.replaceChildren(
      ...rows.flatMap(([k, v]) => [make('dt', { textContent: k }), make('dd', { textContent: v })]),
    );
  }
}
