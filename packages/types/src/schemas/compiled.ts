import { z } from 'zod';
import type { CallSchemas } from './calls.js';

/*
 * Every public HAL call is validated, and zod's interpreted `safeParse` builds a payload object
 * per schema node and copies the input: most of what the HAL layer would add to a call. zod's
 * supported answer is `z.compile(schema)`: a clone of the schema whose parse first runs a
 * function generated once from the schema, and hands anything that function does not accept to
 * the ordinary parser, so a refusal and its issues are exactly zod's. A schema zod cannot
 * compile is handed back unchanged and keeps the ordinary parser. compiled.property.test.ts holds
 * the compiled call schemas of three robots to the ordinary ones, input for input.
 */

/** The call schemas with zod's compiled fast path; each parses as its source schema does. */
export function compileCallSchemas(schemas: CallSchemas): CallSchemas {
  const compiled: Record<string, z.ZodType> = {};
  for (const [name, schema] of Object.entries(schemas)) {
    compiled[name] = z.compile(schema as z.ZodType);
  }
  return compiled as CallSchemas;
}
