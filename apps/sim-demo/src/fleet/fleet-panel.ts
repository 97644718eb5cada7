import { FLEET_MODES, FORMATION_SHAPES, formationOffsets } from '@hal/fleet';
import type {
  FleetMode,
  FleetReport,
  FormationReport,
  FormationShape,
  LeaderFollower,
} from '@hal/fleet';
import { isHalError } from '@hal/types';
import { make } from '../dom.js';
import type { ResultsLog } from '../results-log.js';
import type { RobotRoster } from '../robots/roster.js';
import type { StatusLine } from '../status-line.js';
import type { DemoFleet } from './demo-fleet.js';
import { describeCommand, PANEL_COMMANDS, panelCommand } from './panel-commands.js';
import type { PanelCommandName } from './panel-commands.js';

/** What the card shows, for the end-to-end test. */
export interface FleetPanelState {
  mode: FleetMode;
  busy: boolean;
  /** The last command's per-robot results (independent or synchronized). */
  lastReport: {
    success: boolean;
    results: Array<{ device: string; success: boolean; code?: string }>;
  } | null;
  formation: { running: boolean; leader: string; shape: FormationShape } | null;
  /** How the last formation ended. */
  formationEnd: string | null;
  estopped: boolean;
}

const MODE_HELP: Record<FleetMode, string> = {
  independent:
    'Each robot on its own: the command goes to the selected robot only (the keys, clicks and panels drive it too).',
  synchronized: 'One command to every robot, issued together; each robot reports its own result.',
  'leader-follower':
    'The selected robot leads: drive it with the keys or a click, and the others keep their slots behind it.',
};

/** Formation spacing, metres. */
const SPACING_M = 0.35;

/**
 * The Fleet card: the mode (independent, synchronized, leader-follower), a command for the
 * selected robot or every robot with each robot's own result, a formation behind the selected
 * leader, and the fleet e-stop. All through `@hal/fleet`; this card only asks and shows.
 */
export class FleetPanel {
  readonly state: FleetPanelState = {
    mode: 'independent',
    busy: false,
    lastReport: null,
    formation: null,
    formationEnd: null,
    estopped: false,
  };
  readonly #demo: DemoFleet;
  readonly #roster: RobotRoster;
  readonly #log: ResultsLog;
  readonly #status: StatusLine;
  readonly #mode = make('select', { id: 'fleet-mode', ariaLabel: 'Fleet mode' });
  readonly #help = make('p', { className: 'fleet-help' });
  readonly #command = make('select', { id: 'fleet-command', ariaLabel: 'Fleet command' });
  readonly #amount = make('input', { id: 'fleet-amount', type: 'number', ariaLabel: 'Amount' });
  readonly #unit = make('span', { className: 'muted' });
  readonly #send = make('button', { id: 'fleet-send', textContent: 'Send' });
  readonly #commandRow = make('div', { className: 'fleet-row' });
  readonly #shape = make('select', { id: 'formation-shape', ariaLabel: 'Formation' });
  readonly #formationButton = make('button', {
    id: 'formation-toggle',
    textContent: 'Start formation',
  });
  readonly #formationRow = make('div', { className: 'fleet-row' });
  readonly #estop = make('button', {
    id: 'fleet-estop',
    className: 'estop',
    textContent: 'FLEET E-STOP',
    title: 'Latch the emergency stop of every robot at once',
  });
  readonly #results = make('ol', { id: 'fleet-results', className: 'fleet-results' });

  constructor(
    root: HTMLElement,
    demo: DemoFleet,
    roster: RobotRoster,
    log: ResultsLog,
    status: StatusLine,
  ) {
    this.#demo = demo;
    this.#roster = roster;
    this.#log = log;
    this.#status = status;
    for (const mode of FLEET_MODES)
      this.#mode.append(make('option', { value: mode, textContent: mode }));
    for (const [name, c] of Object.entries(PANEL_COMMANDS)) {
      this.#command.append(make('option', { value: name, textContent: c.label }));
    }
    for (const shape of FORMATION_SHAPES)
      this.#shape.append(make('option', { value: shape, textContent: shape }));
    this.#shape.value = 'wedge';
    this.#commandRow.append(this.#command, this.#amount, this.#unit, this.#send);
    this.#formationRow.append(make('label', {}, 'Formation ', this.#shape), this.#formationButton);
    root.append(
      make('h2', {}, 'Fleet ', make('span', { className: 'muted' }, '@hal/fleet')),
      make('div', { className: 'fleet-row' }, make('label', {}, 'Mode ', this.#mode)),
      this.#help,
      this.#commandRow,
      this.#formationRow,
      this.#results,
      this.#estop,
    );
    this.#mode.addEventListener('change', () => void this.#setMode(this.#mode.value as FleetMode));
    this.#command.addEventListener('change', () => this.#showCommand());
    this.#send.addEventListener('click', () => void this.#sendCommand());
    this.#formationButton.addEventListener('click', () => void this.#toggleFormation());
    this.#estop.addEventListener('click', () => void this.#toggleEstop());
    for (const control of [this.#mode, this.#command, this.#shape]) {
      control.addEventListener('change', () => control.blur());
    }
    this.#showCommand();
    this.#render();
  }

  /** While a formation runs: each follower's distance to its slot, metres (for the test). */
  slotErrors(): Array<{ device: string; errorM: number }> {
    const formation = this.#demo.fleet.formation;
    if (formation === undefined) return [];
    return Object.entries(formation.slots()).map(([device, slot]) => {
      const robot = this.#roster.robot(device).hal.robot;
      return { device, errorM: Math.hypot(robot.x - slot.x, robot.y - slot.y) };
    });
  }

  /** The roster changed: the fleet follows it (a running formation stops). */
  robotsChanged(): void {
    const leader = this.state.formation?.leader;
    const before = this.#demo.fleet.formation;
    if (leader !== undefined && before !== undefined && this.#roster.selected.id !== leader) {
      // The leader is the selected robot: a new selection ends the formation.
      void before.stop();
    }
    this.#demo.sync();
  }

  async #setMode(mode: FleetMode): Promise<void> {
    if (this.#demo.fleet.formation !== undefined) await this.#demo.fleet.formation.stop();
    this.state.mode = mode;
    this.#render();
  }

  #showCommand(): void {
    const spec = PANEL_COMMANDS[this.#command.value as PanelCommandName];
    this.#amount.value = String(spec.initial);
    this.#unit.textContent = spec.unit;
  }

  async #sendCommand(): Promise<void> {
    this.#send.blur();
    const fleet = this.#demo.fleet;
    const name = this.#command.value as PanelCommandName;
    const amount = Number(this.#amount.value === '' ? Number.NaN : this.#amount.value);
    const what = describeCommand(name, amount);
    this.#busy(true);
    try {
      const command = panelCommand(name, amount);
      const report =
        this.state.mode === 'synchronized'
          ? await fleet.synchronized(command)
          : await fleet.independent(this.#roster.selected.id, command).then((r) => ({
              success: r.result.success,
              results: [r],
            }));
      this.#showReport(what, report);
    } catch (error) {
      // A malformed command is refused before anything moves.
      this.#status.set(
        `${what}: ${isHalError(error) ? `${error.code}: ${error.message}` : String(error)}`,
        'bad',
      );
    } finally {
      this.#busy(false);
    }
  }

  async #toggleFormation(): Promise<void> {
    this.#formationButton.blur();
    const fleet = this.#demo.fleet;
    const running = fleet.formation;
    if (running !== undefined) {
      await running.stop();
      return;
    }
    const leader = this.#roster.selected;
    const followers = this.#roster.robots.filter((r) => r !== leader).map((r) => r.id);
    const shape = this.#shape.value as FormationShape;
    try {
      const formation = await fleet.leaderFollower({
        leader: leader.id,
        formation: formationOffsets(shape, followers, SPACING_M),
        // The formation holds until you stop it, not when the leader pauses.
        stopWhenLeaderStops: false,
      });
      this.state.formation = { running: true, leader: leader.id, shape };
      this.state.formationEnd = null;
      this.#status.set(`${leader.label} leads a ${shape}: drive it, the others follow`);
      this.#render();
      void formation.done.then((report) => this.#formationEnded(formation, report));
    } catch (error) {
      this.#status.set(
        isHalError(error) ? `${error.code}: ${error.message}` : String(error),
        'bad',
      );
    }
  }

  #formationEnded(formation: LeaderFollower, report: FormationReport): void {
    if (this.#demo.fleet.formation !== undefined && this.#demo.fleet.formation !== formation)
      return;
    this.state.formation = null;
    const worst = Math.max(0, ...report.followers.map((f) => f.errorM ?? 0));
    this.state.formationEnd = report.reason;
    this.#log.note(
      `formation ended (${report.reason}${report.estopDevice === undefined ? '' : ` by ${report.estopDevice}`}), farthest follower ${(worst * 100).toFixed(1)} cm from its slot`,
    );
    this.#render();
  }

  async #toggleEstop(): Promise<void> {
    this.#estop.blur();
    const fleet = this.#demo.fleet;
    if (fleet.isEmergencyStopped()) {
      const report = await fleet.resetEmergencyStop();
      this.#showReport('reset fleet e-stop', report);
      if (report.success) this.#status.set('Fleet e-stop cleared on every robot');
      else this.#status.set('The fleet e-stop stays latched: a robot refused its reset', 'bad');
    } else {
      const pending = fleet.emergencyStop('fleet e-stop button in the demo');
      this.state.estopped = true;
      this.#render();
      this.#showReport('FLEET E-STOP', await pending);
      this.#status.set('FLEET E-STOP latched on every robot: reset it here', 'bad');
    }
    this.state.estopped = fleet.isEmergencyStopped();
    this.#render();
  }

  /** Lists each robot's own result of a fleet call. */
  #showReport(what: string, report: Pick<FleetReport, 'success' | 'results'>): void {
    this.state.lastReport = {
      success: report.success,
      results: report.results.map(({ device, result }) => ({
        device,
        success: result.success,
        ...(result.code === undefined ? {} : { code: result.code }),
      })),
    };
    const items = report.results.map(({ device, result }) => {
      const label = this.#labelOf(device);
      const secs = ((result.executionTime ?? 0) / 1000).toFixed(1);
      const item = make(
        'li',
        { className: result.success ? 'pass' : 'fail' },
        result.success ? `${label} ✓ ${secs} s` : `${label} ✗ ${result.code}: ${result.error}`,
      );
      item.dataset.robotId = device;
      return item;
    });
    this.#results.replaceChildren(make('li', { className: 'event' }, what), ...items);
    const failed = report.results.filter((r) => !r.result.success).length;
    this.#log.note(`fleet: ${what}: ${report.results.length - failed} ok, ${failed} failed`);
  }

  #labelOf(device: string): string {
    return this.#roster.robots.find((r) => r.id === device)?.label ?? device;
  }

  #busy(busy: boolean): void {
    this.state.busy = busy;
    this.#send.disabled = busy;
  }

  #render(): void {
    const { mode } = this.state;
    this.#mode.value = mode;
    this.#help.textContent = MODE_HELP[mode];
    this.#commandRow.hidden = mode === 'leader-follower';
    this.#send.textContent = mode === 'synchronized' ? 'Send to all' : 'Send to selected';
    this.#formationRow.hidden = mode !== 'leader-follower';
    const running = this.#demo.fleet.formation !== undefined;
    this.#formationButton.textContent = running ? 'Stop formation' : 'Start formation';
    this.#shape.disabled = running;
    const latched = this.#demo.fleet.isEmergencyStopped();
    this.#estop.textContent = latched ? 'RESET FLEET E-STOP' : 'FLEET E-STOP';
    this.#estop.classList.toggle('latched', latched);
  }
}
