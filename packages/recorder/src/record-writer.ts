import type { McapTypes } from '@mcap/core';

/**
 * What a recorder needs of an MCAP writer: `@mcap/core`'s McapWriter on the caller's thread, or
 * {@link WorkerWriter}, which hands the records to a worker thread that runs one.
 */
export interface RecordWriter {
  start(header: McapTypes.Header): Promise<void>;
  registerSchema(schema: Omit<McapTypes.Schema, 'id'>): Promise<number>;
  registerChannel(channel: Omit<McapTypes.Channel, 'id'>): Promise<number>;
  addMessage(message: McapTypes.Message): Promise<void>;
  addMetadata(metadata: McapTypes.Metadata): Promise<void>;
  end(): Promise<void>;
}
