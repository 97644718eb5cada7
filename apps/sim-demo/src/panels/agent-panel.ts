import { runAgent } from '@hal/agent';
import type { AgentEvent } from '@hal/agent';
import type { HardwareAbstractionLayer } from '@hal/types';
import './agent-panel.css';
import { errorMessage } from '@hal/types';
import { loadAgentSettings, saveAgentSettings } from './agent-settings.js';

/** How many event lines the panel keeps. */
const KEPT = 200;

const clip = (text: string, n = 240) => (text.length > n ? `${text.slice(0, n)}…` : text);

/** One event as a line of the panel's log, with its class (none for streamed tokens). */
function eventLine(e: AgentEvent): { text: string; className: string } | undefined {
  switch (e.type) {
    case 'token':
    case 'usage':
      return undefined;
    case 'context_trimmed':
      return {
        text: `Context full: ${e.droppedMessages} older messages left out`,
        className: 'event',
      };
    case 'step_started':
      return { text: `Step ${e.step}`, className: 'step' };
    case 'assistant_text':
      return { text: `Model: ${clip(e.text)}`, className: 'say' };
    case 'tool_call':
      return { text: `→ ${e.name} ${clip(e.arguments, 120)}`, className: 'call' };
    case 'tool_result':
      return {
        text: `${e.isError ? '✗' : '✓'} ${e.name}${e.code === undefined ? '' : ` ${e.code}`}: ${clip(e.text, 160)}${e.image ? ' [frame]' : ''}`,
        className: e.isError ? 'fail' : 'pass',
      };
    case 'retry':
      return {
        text: `Retry ${e.attempt} in ${e.delayMs} ms: ${clip(e.reason, 120)}`,
        className: 'event',
      };
    case 'error':
      return {
        text: `Endpoint error ${e.error.code}: ${clip(e.error.message)}`,
        className: 'fail',
      };
    case 'done':
      return {
        text: `Done: ${e.reason} after ${e.steps} step${e.steps === 1 ? '' : 's'}`,
        className: e.reason === 'completed' ? 'pass' : 'fail',
      };
  }
}

const TEMPLATE = `
  <h2>Agent <span class="muted">an LLM drives the robot</span></h2>
  <form class="agent-form" id="agent-form">
    <label>Endpoint <input id="agent-url" type="url" required placeholder="https://api.openai.com/v1" autocomplete="off" /></label>
    <label>Model <input id="agent-model" required placeholder="gpt-4o-mini, qwen2.5vl:7b" autocomplete="off" /></label>
    <label>API key <input id="agent-key" type="password" placeholder="none for a local server" autocomplete="off" /></label>
    <p class="muted agent-note">The key stays in this tab (sessionStorage) and is sent only to the endpoint above. Any OpenAI-compatible chat-completions server with tool calling; it must allow this page's origin (CORS).</p>
    <label>Instruction <textarea id="agent-goal" rows="2" required placeholder="Drive 30 cm forward, then turn left and tell me what you see"></textarea></label>
    <div class="agent-buttons">
      <button id="agent-run" type="submit">Run</button>
      <button id="agent-stop" type="button" class="secondary" disabled>Stop</button>
      <span id="agent-state" class="muted" role="status">Idle</span>
    </div>
  </form>
  <ol class="log agent-log" id="agent-log"></ol>`;

/**
 * The Agent panel: an endpoint, a model, a key and an instruction; Run starts `runAgent` on the
 * demo's HAL and streams its events into the list; Stop aborts the run, which stops the robot.
 */
export class AgentPanel {
  readonly #hal: HardwareAbstractionLayer;
  readonly #root: HTMLElement;
  #controller: AbortController | undefined;

  constructor(root: HTMLElement, hal: HardwareAbstractionLayer) {
    this.#hal = hal;
    this.#root = root;
    root.classList.add('card', 'agent-panel');
    root.innerHTML = TEMPLATE;
    const saved = loadAgentSettings();
    this.#input('agent-url').value = saved.baseUrl;
    this.#input('agent-model').value = saved.model;
    this.#input('agent-key').value = saved.apiKey;
    this.#find<HTMLFormElement>('agent-form').addEventListener('submit', (e) => {
      e.preventDefault();
      void this.run();
    });
    this.#find('agent-stop').addEventListener('click', () => this.stop());
    // Typing in the form must not drive the robot: the page's teleop keys (arrows, WASD, Space)
    // listen on the window, so keys stop here, all but Escape (the e-stop).
    for (const type of ['keydown', 'keyup'] as const) {
      root.addEventListener(type, (e) => {
        if (e.key !== 'Escape') e.stopPropagation();
      });
    }
  }

  /** Whether a run is going on. */
  get running(): boolean {
    return this.#controller !== undefined;
  }

  /** Runs the instruction in the form. */
  async run(): Promise<void> {
    if (this.#controller !== undefined) return;
    const settings = {
      baseUrl: this.#input('agent-url').value.trim(),
      model: this.#input('agent-model').value.trim(),
      apiKey: this.#input('agent-key').value,
    };
    saveAgentSettings(settings);
    const goal = this.#find<HTMLTextAreaElement>('agent-goal').value.trim();
    const controller = new AbortController();
    this.#controller = controller;
    this.#setRunning(true);
    this.#find('agent-log').replaceChildren();
    try {
      const outcome = await runAgent({
        goal,
        hal: this.#hal,
        endpoint: {
          baseUrl: settings.baseUrl,
          model: settings.model,
          ...(settings.apiKey === '' ? {} : { apiKey: settings.apiKey }),
        },
        caps: { maxSteps: 30, maxMs: 10 * 60_000 },
        signal: controller.signal,
        onEvent: (event) => this.#show(event),
      });
      this.#state(outcome.reason === 'completed' ? 'Done' : `Ended: ${outcome.reason}`);
    } catch (error) {
      // Only bad settings get here (runAgent reports endpoint failures as events).
      this.#add({
        text: errorMessage(error),
        className: 'fail',
      });
      this.#state('Check the settings');
    } finally {
      this.#controller = undefined;
      this.#setRunning(false);
    }
  }

  /** Aborts the run; the loop stops the robot, and so does this, at once. */
  stop(): void {
    if (this.#controller === undefined) return;
    this.#state('Stopping…');
    this.#controller.abort();
    void this.#hal.locomotion.stop();
  }

  #show(event: AgentEvent): void {
    const line = eventLine(event);
    if (line !== undefined) this.#add(line);
    if (event.type === 'step_started') this.#state(`Step ${event.step}…`);
  }

  #add(line: { text: string; className: string }): void {
    const list = this.#find('agent-log');
    const item = document.createElement('li');
    item.className = line.className;
    item.textContent = line.text;
    list.append(item);
    while (list.children.length > KEPT) list.firstElementChild?.remove();
    list.scrollTop = list.scrollHeight;
  }

  #setRunning(running: boolean): void {
    this.#find<HTMLButtonElement>('agent-run').disabled = running;
    this.#find<HTMLButtonElement>('agent-stop').disabled = !running;
    if (running) this.#state('Running…');
  }

  #state(text: string): void {
    this.#find('agent-state').textContent = text;
  }

  #input(id: string): HTMLInputElement {
    return this.#find<HTMLInputElement>(id);
  }

  #find<T extends HTMLElement = HTMLElement>(id: string): T {
    const found = this.#root.querySelector<T>(`#${id}`);
    if (found === null) throw new Error(`#${id} is missing from the agent panel`);
    return found;
  }
}
