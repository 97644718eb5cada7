import { errorMessage } from '@hal/types';
import { make } from '../dom.js';
import type { StatusLine } from '../status-line.js';
import { MAX_ROBOTS } from './palette.js';
import type { RobotRoster } from './roster.js';

/**
 * The "Robots" card: one button per robot (its colour, label and state; click to select the
 * robot the page drives), "Add robot" and "Remove". Errors (at most eight robots, no free place,
 * the last robot) go to the status line.
 */
export class RobotsCard {
  readonly #roster: RobotRoster;
  readonly #status: StatusLine;
  readonly #list = make('div', { className: 'robot-list', id: 'robot-list' });
  readonly #count = make('span', { className: 'muted', id: 'robot-count' });
  readonly #add = make('button', {
    id: 'add-robot',
    className: 'secondary',
    textContent: '+ Add robot',
  });
  readonly #remove = make('button', {
    id: 'remove-robot',
    className: 'secondary',
    textContent: 'Remove',
  });
  readonly #states = new Map<string, HTMLElement>();

  constructor(root: HTMLElement, roster: RobotRoster, status: StatusLine) {
    this.#roster = roster;
    this.#status = status;
    this.#add.title = `Add a simulated robot to the world (at most ${MAX_ROBOTS})`;
    this.#remove.title = 'Remove the selected robot from the world';
    root.append(
      make('h2', {}, 'Robots ', this.#count),
      this.#list,
      make('div', { className: 'robot-actions' }, this.#add, this.#remove),
    );
    this.#add.addEventListener(
      'click',
      () =>
        void this.#run(async () => {
          const robot = await roster.add();
          roster.select(robot.id);
        }),
    );
    this.#remove.addEventListener(
      'click',
      () => void this.#run(() => roster.remove(roster.selected.id)),
    );
    roster.onChange(() => this.#rebuild());
    this.#rebuild();
  }

  /** Refreshes each robot's state line (call a few times a second). */
  refresh(): void {
    for (const robot of this.#roster.robots) {
      const state = this.#states.get(robot.id);
      const sim = robot.hal.robot;
      const text = sim.emergencyStopped
        ? 'E-STOP'
        : `${sim.x.toFixed(2)}, ${sim.y.toFixed(2)} m${sim.running ? ' · moving' : ''}`;
      if (state !== undefined && state.textContent !== text) state.textContent = text;
    }
  }

  async #run(action: () => Promise<void>): Promise<void> {
    this.#add.blur();
    this.#remove.blur();
    try {
      await action();
    } catch (error) {
      this.#status.set(errorMessage(error), 'bad');
    }
  }

  #rebuild(): void {
    const roster = this.#roster;
    this.#states.clear();
    const buttons = roster.robots.map((robot) => {
      const state = make('span', { className: 'robot-state' });
      this.#states.set(robot.id, state);
      const swatch = make('span', { className: 'swatch' });
      swatch.style.background = robot.color;
      const selected = robot === roster.selected;
      const button = make(
        'button',
        { className: `robot-item${selected ? ' selected' : ''}`, title: `Drive ${robot.label}` },
        swatch,
        make('strong', {}, robot.label),
        state,
      );
      button.dataset.robotId = robot.id;
      button.setAttribute('aria-pressed', String(selected));
      button.addEventListener('click', () => {
        button.blur();
        roster.select(robot.id);
      });
      return button;
    });
    this.#list.replaceChildren(...buttons);
    this.#count.textContent = `${roster.robots.length} of ${MAX_ROBOTS} · ${roster.selected.label} selected`;
    this.#add.disabled = roster.robots.length >= MAX_ROBOTS;
    this.#remove.disabled = roster.robots.length <= 1;
    this.refresh();
  }
}
