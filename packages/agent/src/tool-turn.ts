import type { ToolResult } from '@hal/tools';
import type { ChatContentPart, ChatMessage } from './chat-types.js';

/** The text of a tool result as the model receives it in the `tool` message. */
export function resultText(result: ToolResult): string {
  const text = result.content
    .flatMap((part) => (part.type === 'text' ? [part.text] : []))
    .join('\n');
  const images = result.content.filter((part) => part.type === 'image').length;
  if (text !== '') return text;
  return images > 0 ? '(the camera frame follows as an image)' : '(no output)';
}

/** The images of a tool result as chat `image_url` parts (data URLs). */
export function resultImages(result: ToolResult): ChatContentPart[] {
  return result.content.flatMap((part) =>
    part.type === 'image'
      ? [
          {
            type: 'image_url' as const,
            image_url: { url: `data:${part.mimeType};base64,${part.data}` },
          },
        ]
      : [],
  );
}

/**
 * The user message that carries a turn's camera frames: chat-completions `tool` messages can only
 * hold text, so images go in a user message right after the turn's tool messages.
 */
export function imagesMessage(
  images: Array<{ callId: string; name: string; parts: ChatContentPart[] }>,
): ChatMessage | undefined {
  if (images.length === 0) return undefined;
  const content: ChatContentPart[] = [];
  for (const image of images) {
    content.push({ type: 'text', text: `Camera frame from ${image.name} (call ${image.callId}):` });
    content.push(...image.parts);
  }
  return { role: 'user', content };
}
