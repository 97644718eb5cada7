// @hal/agent-local/grammar: the reply grammar on its own, for a program that drives node-llama-cpp
// itself (the benchmark compares the provider with node-llama-cpp alone under the same grammar).
// Its types are node-llama-cpp's (`Llama`, `LlamaGrammar`, `GbnfJsonOneOfSchema`), so importing
// it needs node-llama-cpp installed; the main entry's types need nothing of node-llama-cpp (so
// nothing of grammar-schema.ts or grammar.ts is exported there).
export { replySchema } from './grammar-schema.js';
export { replyGrammar } from './grammar.js';
