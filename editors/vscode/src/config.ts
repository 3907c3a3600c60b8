// From the extension's settings (smachac.*) to the server's command line and to the settings
// the server reads (initializationOptions, workspace/configuration, didChangeConfiguration).
// Pure: no `vscode` import, so that plain Node tests it (src/test/config.test.ts).
import * as os from 'node:os';
import * as path from 'node:path';

/** The configuration section, and the settings object's key in the server's requests. */
export const SECTION = 'smachac';

/** The documents the server is given: YAML files on disk and unsaved YAML buffers. */
export const DOCUMENT_SELECTOR = [
  { scheme: 'file', language: 'yaml' },
  { scheme: 'untitled', language: 'yaml' },
];

export const TARGETS = ['smach', 'flexbe', 'cpp'] as const;
export type Target = (typeof TARGETS)[number];

/** The compiler's default target, used when the setting is absent or not one of TARGETS. */
export const DEFAULT_TARGET: Target = 'smach';
export const DEFAULT_EXECUTABLE = 'smachac';

/** The settings below `smachac.` that package.json contributes (trace.server: the client's). */
export const SETTING_KEYS = [
  'path',
  'target',
  'templateDirs',
  'scriptDirs',
  'warnings',
  'trace.server',
] as const;

/** The settings as the editor gives them: values not checked yet. */
export interface RawSettings {
  path?: unknown;
  target?: unknown;
  templateDirs?: unknown;
  scriptDirs?: unknown;
  warnings?: unknown;
}

/** What `smachac lsp` reads from initializationOptions and workspace/configuration. */
export interface ServerSettings {
  target: Target;
  templateDirs: string[];
  scriptDirs: string[];
  warnings: string[];
}

export interface ServerCommand {
  command: string;
  args: string[];
  /** The workspace folder, when there is one: the server's working directory. */
  cwd?: string;
}

/**
 * Expands `~` and `${workspaceFolder}` / `${userHome}` in a path, then resolves it against the
 * workspace folder when it is relative. Without a folder a relative path stays as it is.
 */
export function expandPath(value: string, folder: string | undefined, home = os.homedir()): string {
  let p = value.trim();
  if (folder !== undefined) p = p.split('${workspaceFolder}').join(folder);
  p = p.split('${userHome}').join(home);
  if (p === '~') {
    p = home;
  } else if (p.startsWith('~/') || p.startsWith('~\\')) {
    p = path.join(home, p.slice(2));
  }
  if (path.isAbsolute(p)) return path.normalize(p);
  return folder !== undefined ? path.resolve(folder, p) : p;
}

/** A list setting's non-empty strings, expanded and resolved, first occurrence kept. */
export function resolveDirs(value: unknown, folder: string | undefined, home = os.homedir()): string[] {
  if (!Array.isArray(value)) return [];
  const dirs: string[] = [];
  for (const item of value) {
    if (typeof item !== 'string' || item.trim() === '') continue;
    const dir = expandPath(item, folder, home);
    if (!dirs.includes(dir)) dirs.push(dir);
  }
  return dirs;
}

/**
 * Warning options in the command line's spelling: `-Werror` stays, `Werror` and `error`
 * become `-Werror`. Empty entries are dropped; the order is kept (later options win).
 */
export function warningOptions(value: unknown): string[] {
  if (!Array.isArray(value)) return [];
  const options: string[] = [];
  for (const item of value) {
    if (typeof item !== 'string') continue;
    const w = item.trim();
    if (w === '' || w === '-W' || w === 'W') continue;
    if (w.startsWith('-W')) options.push(w);
    else if (w.startsWith('W')) options.push('-' + w);
    else options.push('-W' + w.replace(/^-+/, ''));
  }
  return options;
}

export function targetOf(value: unknown): Target {
  return (TARGETS as readonly unknown[]).includes(value) ? (value as Target) : DEFAULT_TARGET;
}

/** The settings object sent to the server, relative directories resolved against `folder`. */
export function serverSettings(raw: RawSettings, folder: string | undefined, home = os.homedir()): ServerSettings {
  return {
    target: targetOf(raw.target),
    templateDirs: resolveDirs(raw.templateDirs, folder, home),
    scriptDirs: resolveDirs(raw.scriptDirs, folder, home),
    warnings: warningOptions(raw.warnings),
  };
}

/**
 * The server's command line: `<smachac.path> lsp`. A bare name (no path separator) is left to
 * the PATH lookup; a path is expanded and resolved against the workspace folder. The other
 * settings go in initializationOptions only, so that a later didChangeConfiguration can
 * change every one of them.
 */
export function serverCommand(raw: RawSettings, folder: string | undefined, home = os.homedir()): ServerCommand {
  let command = typeof raw.path === 'string' ? raw.path.trim() : '';
  if (command === '') command = DEFAULT_EXECUTABLE;
  const isBareName = !/[\\/]/.test(command) && !command.startsWith('~') && !command.includes('${');
  if (!isBareName) command = expandPath(command, folder, home);
  const result: ServerCommand = { command, args: ['lsp'] };
  if (folder !== undefined) result.cwd = folder;
  return result;
}

/**
 * The answer to one item of a workspace/configuration request: the settings object for the
 * section `smachac`, one of its values for `smachac.<key>`, undefined for other sections.
 */
export function configurationItem(section: string | undefined, settings: ServerSettings): unknown {
  if (section === SECTION) return settings;
  if (section !== undefined && section.startsWith(SECTION + '.')) {
    const key = section.slice(SECTION.length + 1) as keyof ServerSettings;
    return Object.prototype.hasOwnProperty.call(settings, key) ? settings[key] : null;
  }
  return undefined;
}
