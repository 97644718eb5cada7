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

/**
 * Notes the HAL's communication events, collisions and host timeouts in `log`, each after
 * `label` (the robot's, when there are several). Returns the function that stops it.
 */
export function noteHalEvents(hal: SimulationHAL, log: ResultsLog, label = ''): () => void {
  const note = (text: string) => log.note(label === '' ? text : `${label}: ${text}`);
  const offCommunication = hal.events.on('communication', (e) => {
    if (e.type === 'led') note(`LED ${e.pattern} rgb(${e.r}, ${e.g}, ${e.b})`);
    else if (e.type === 'log') note(`log [${e.level}] ${e.message}`);
    else if (e.type === 'speak') note(`says "${e.text}"`);
    else note(`plays ${e.soundId}`);
  });
  const offMotion = hal.events.on('motionFinished', (m) => {
    if (m.outcome === 'collision' && m.contact !== undefined) {
      const p = m.contact.point;
      const what = m.contact.robotId === undefined ? m.contact.role : m.contact.robotId;
      note(
        `bumped into ${m.contact.role === 'robot' ? '' : 'a '}${what} at (${p.x.toFixed(2)}, ${p.y.toFixed(2)}) m`,
      );
    } else if (m.outcome === 'host_timeout') {
      note('host timeout: the robot stopped by itself');
    }
  });
  return () => {
    offCommunication();
    offMotion();
  };
}
