import type { JsonSchemaObject } from './json-schema.js';
import type { AgentTool } from './tools.js';

/** An OpenAI chat-completions tool. */
export interface OpenAITool {
  type: 'function';
  function: { name: string; description: string; parameters: JsonSchemaObject };
}

/** An Anthropic Messages API tool. */
export interface AnthropicTool {
  name: string;
  description: string;
  input_schema: JsonSchemaObject;
}

/** An MCP tool (as `tools/list` lists it). */
export interface McpTool {
  name: string;
  description: string;
  inputSchema: JsonSchemaObject;
}

/** The tools in OpenAI chat-completions form (`tools: [...]`). */
export function toOpenAITools(tools: readonly AgentTool[]): OpenAITool[] {
  return tools.map((t) => ({
    type: 'function',
    function: { name: t.name, description: t.description, parameters: t.inputSchema },
  }));
}

/** The tools in Anthropic Messages API form. */
export function toAnthropicTools(tools: readonly AgentTool[]): AnthropicTool[] {
  return tools.map((t) => ({
    name: t.name,
    description: t.description,
    input_schema: t.inputSchema,
  }));
}

/** The tools in MCP `tools/list` form. */
export function toMcpTools(tools: readonly AgentTool[]): McpTool[] {
  return tools.map((t) => ({
    name: t.name,
    description: t.description,
    inputSchema: t.inputSchema,
  }));
}

/** Each tool's parameter schema, by tool name. */
export function toJsonSchemas(tools: readonly AgentTool[]): Record<string, JsonSchemaObject> {
  return Object.fromEntries(tools.map((t) => [t.name, t.inputSchema]));
}
