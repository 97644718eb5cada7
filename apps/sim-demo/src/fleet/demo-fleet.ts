import { Fleet } from '@hal/fleet';
import type { Logger } from '@hal/types';
import type { RobotRoster } from '../robots/roster.js';

/**
 * The demo's robots as a `@hal/fleet` Fleet: one member per robot (its id, its own HAL), kept in
 * step with the Robots card. Call {@link sync} whenever the roster changes; a running formation
 * is stopped first (its members may be gone), and when the map changes.
 *
 * The fleet runs on the wall clock (its default), not on the world's: the real-time ticker moves
 * the world in bursts of many ticks between two browser tasks, and a simulated-time timeout
 * would fire inside such a burst before a HAL's answer (a resolved promise) could be read.
 */
export class DemoFleet {
  readonly fleet: Fleet;
  readonly #roster: RobotRoster;

  /** `logger`: where the fleet's warnings go (the demo's results list). */
  constructor(roster: RobotRoster, logger?: Logger) {
    this.#roster = roster;
    this.fleet = new Fleet([], logger === undefined ? {} : { logger });
    // A new map puts every robot at a start again: a formation's slots no longer mean anything.
    roster.world.events.on('map', () => void this.fleet.formation?.stop());
    this.sync();
  }

  /** Makes the fleet's members the roster's robots (by id, each with its HAL). */
  sync(): void {
    const fleet = this.fleet;
    const ids = new Set(this.#roster.robots.map((r) => r.id));
    const changed = fleet.devices.length !== ids.size || fleet.devices.some((id) => !ids.has(id));
    if (!changed) return;
    if (fleet.formation !== undefined) void fleet.formation.stop();
    for (const id of fleet.devices) if (!ids.has(id)) fleet.remove(id);
    for (const robot of this.#roster.robots) {
      if (!fleet.devices.includes(robot.id)) fleet.add({ id: robot.id, hal: robot.hal });
    }
  }
}
