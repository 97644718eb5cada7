/** The endpoint the Agent panel talks to, as the user typed it. */
export interface AgentPanelSettings {
  baseUrl: string;
  model: string;
  apiKey: string;
}

const STORAGE_KEY = 'hal-sim-demo:agent';

/**
 * The settings kept in this tab's sessionStorage (gone when the tab closes), never in
 * localStorage or a cookie, so the key leaves the browser only in requests to the endpoint.
 */
export function loadAgentSettings(storage: Storage = sessionStorage): AgentPanelSettings {
  const empty = { baseUrl: 'http://127.0.0.1:11434/v1', model: '', apiKey: '' };
  try {
    const saved = JSON.parse(storage.getItem(STORAGE_KEY) ?? '{}') as Partial<AgentPanelSettings>;
    return {
      baseUrl: typeof saved.baseUrl === 'string' ? saved.baseUrl : empty.baseUrl,
      model: typeof saved.model === 'string' ? saved.model : empty.model,
      apiKey: typeof saved.apiKey === 'string' ? saved.apiKey : empty.apiKey,
    };
  } catch {
    return empty;
  }
}

export function saveAgentSettings(
  settings: AgentPanelSettings,
  storage: Storage = sessionStorage,
): void {
  storage.setItem(STORAGE_KEY, JSON.stringify(settings));
}
