/** The one-line status over the viewport: what the demo is doing, or why it stopped. */
export class StatusLine {
  readonly #element: HTMLElement;

  constructor(element: HTMLElement) {
    this.#element = element;
  }

  set(text: string, tone: 'info' | 'ok' | 'bad' = 'info'): void {
    this.#element.textContent = text;
    this.#element.className = `status${tone === 'info' ? '' : ` ${tone}`}`;
  }
}
