import type { McapTypes } from '@mcap/core';

/** One message of a recording, its JSON decoded. */
export interface RecordedMessage {
  topic: string;
  schemaName: string;
  logTime: bigint;
  value: unknown;
}

/** A topic of a recording: its schema's name, the JSON Schema it declares, its message count. */
export interface RecordedChannel {
  schemaName: string;
  schema: unknown;
  messageCount: number;
}

const decoder = new TextDecoder();

/** Collects a recording's records as a reader hands them over (in the file's order). */
export class RecordingBuilder {
  readonly schemas = new Map<number, McapTypes.Schema>();
  readonly channelsById = new Map<number, McapTypes.Channel>();
  readonly channels = new Map<string, RecordedChannel>();
  readonly messages: RecordedMessage[] = [];
  readonly metadata = new Map<string, Record<string, string>>();

  schema(record: McapTypes.Schema): void {
    this.schemas.set(record.id, record);
  }

  channel(record: McapTypes.Channel): void {
    this.channelsById.set(record.id, record);
    const schema = this.schemas.get(record.schemaId);
    if (!this.channels.has(record.topic)) {
      this.channels.set(record.topic, {
        schemaName: schema?.name ?? '',
        schema: schema ? (JSON.parse(decoder.decode(schema.data)) as unknown) : undefined,
        messageCount: 0,
      });
    }
  }

  message(record: McapTypes.Message): void {
    const channel = this.channelsById.get(record.channelId);
    if (!channel) throw new Error(`message on unknown channel ${record.channelId}`);
    const value = JSON.parse(decoder.decode(record.data)) as unknown;
    const entry = this.channels.get(channel.topic);
    if (entry) entry.messageCount += 1;
    this.messages.push({
      topic: channel.topic,
      schemaName: entry?.schemaName ?? '',
      logTime: record.logTime,
      value,
    });
  }

  meta(record: McapTypes.Metadata): void {
    this.metadata.set(record.name, Object.fromEntries(record.metadata));
  }

  /** Hands one record of any kind to the builder; false for a kind a recording does not keep. */
  add(record: McapTypes.TypedMcapRecord): boolean {
    if (record.type === 'Schema') this.schema(record);
    else if (record.type === 'Channel') this.channel(record);
    else if (record.type === 'Message') this.message(record);
    else if (record.type === 'Metadata') this.meta(record);
    else return false;
    return true;
  }

  /** The messages in log-time order (a recovered file's chunks come in the file's order). */
  sortedMessages(): RecordedMessage[] {
    return this.messages.sort((a, b) =>
      a.logTime < b.logTime ? -1 : a.logTime > b.logTime ? 1 : 0,
    );
  }
}
