import { make } from '../dom.js';
import type { Viewport } from '../viewport.js';
import type { RobotRoster } from './roster.js';

/** How high over the floor a label floats, metres. */
const LABEL_HEIGHT_M = 0.16;

/** Each robot's label (R1, R2, ...) in its colour, floating over it in the 3D view. */
export class RobotLabels {
  readonly #layer = make('div', { className: 'robot-labels' });
  readonly #roster: RobotRoster;
  readonly #viewport: Viewport;

  constructor(roster: RobotRoster, viewport: Viewport) {
    this.#roster = roster;
    this.#viewport = viewport;
    // Over the 3D canvas, under the minimap and the status line.
    viewport.renderer.domElement.after(this.#layer);
    roster.onChange(() => this.#rebuild());
    this.#rebuild();
  }

  /** Moves every label over its robot (call once per frame, after the camera moved). */
  update(): void {
    const origin = this.#layer.getBoundingClientRect();
    for (const robot of this.#roster.robots) {
      const label = this.#layer.querySelector<HTMLElement>(`[data-robot-id="${robot.id}"]`);
      if (label === null) continue;
      const sim = robot.hal.robot;
      const at = this.#viewport.worldToClient(sim.x, sim.y, LABEL_HEIGHT_M);
      label.style.transform = `translate(${at.x - origin.left}px, ${at.y - origin.top}px) translate(-50%, -100%)`;
    }
  }

  #rebuild(): void {
    const selected = this.#roster.selected;
    this.#layer.replaceChildren(
      ...this.#roster.robots.map((robot) => {
        const label = make('span', {
          className: `robot-label${robot === selected ? ' selected' : ''}`,
          textContent: robot.label,
        });
        label.dataset.robotId = robot.id;
        label.style.background = robot.color;
        return label;
      }),
    );
    this.update();
  }
}
