// A worked example run, as a small model is shown one before its own (see history.ts). Its own
// file: the package's declarations must not reach node-llama-cpp's types, an optional peer.

/**
 * A worked example the model reads before the conversation, as chat turns of its own (a tiny
 * model copies a pattern from earlier turns far better than it follows a description).
 */
export interface ExampleRun {
  /** What the user asks. */
  goal: string;
  /** The model's tool calls, each with the result it got, in order. */
  calls: ReadonlyArray<{ tool: string; arguments: Record<string, unknown>; result: string }>;
  /** The model's final answer. */
  answer: string;
}
