import type { SimulationHAL } from '@hal/simulation';
import type { HALToolResult } from '@hal/types';

/** How many entries the list keeps. */
const KEPT = 30;

/** The "Last results" list: HAL calls with their outcome and notable events, newest first. */
export class ResultsLog {
  readonly #list: HTMLOListElement;

  constructor(list: HTMLOListElement) {
    this.#list = list;
  }

  /** A HAL call and its result. */
  record(call: string, result: HALToolResult): void {
    const secs = ((result.executionTime ?? 0) / 1000).toFixed(1);
    this.#add(
      result.success ? 'pass' : 'fail',
      result.success
        ? `${call} ✓ (${secs} s simulated)`
        : `${call} ✗ ${result.code}: ${result.error}`,
    );
  }

  /** Something that happened. */
  note(text: string): void {
    this.#add('event', text);
  }

  #add(className: string, text: string): void {
    const item = document.createElement('li');
    item.className = className;
    item.textContent = text;
    this.#list.prepend(item);
    while (this.#list.children.length > KEPT) this.#list.lastElementChild?.remove();
  }
}

/** Notes the HAL's communication events, collisions and host timeouts in `log`. */
export function noteHalEvents(hal: SimulationHAL, log: ResultsLog): void {
  hal.events.on('communication', (e) => {
    if (e.type === 'led') log.note(`LED ${e.pattern} rgb(${e.r}, ${e.g}, ${e.b})`);
    else if (e.type === 'log') log.note(`log [${e.level}] ${e.message}`);
    else if (e.type === 'speak') log.note(`says "${e.text}"`);
    else log.note(`plays ${e.soundId}`);
  });
  hal.events.on('motionFinished', (m) => {
    if (m.outcome === 'collision' && m.contact !== undefined) {
      const p = m.contact.point;
      log.note(`bumped into a ${m.contact.role} at (${p.x.toFixed(2)}, ${p.y.toFixed(2)}) m`);
    } else if (m.outcome === 'host_timeout') {
      log.note('host timeout: the robot stopped by itself');
    }
  });
}
