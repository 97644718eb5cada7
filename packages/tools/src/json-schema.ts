import { z } from 'zod';

/** A JSON Schema of an object: what every tool's parameters are. */
export interface JsonSchemaObject {
  type: 'object';
  properties: Record<string, Record<string, unknown>>;
  required?: string[];
  additionalProperties?: boolean;
  description?: string;
  [keyword: string]: unknown;
}

/**
 * The JSON Schema of a call's zod parameter schema, as the call takes it (`io: 'input'`), without
 * the `$schema` line (tool formats embed the schema in their own documents).
 */
export function toolParameters(schema: z.ZodType): JsonSchemaObject {
  const json = z.toJSONSchema(schema, { io: 'input', target: 'draft-2020-12' }) as Record<
    string,
    unknown
  >;
  delete json['$schema'];
  const properties = (json['properties'] ?? {}) as JsonSchemaObject['properties'];
  return { ...json, type: 'object', properties };
}
