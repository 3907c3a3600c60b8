// The VS Code side of `smachac lsp`: starts the server for YAML documents, gives it the
// smachac.* settings (initializationOptions, workspace/configuration, didChangeConfiguration)
// and restarts it on request or when smachac.path changes.
import * as vscode from 'vscode';
import {
  DidChangeConfigurationNotification,
  LanguageClient,
  LanguageClientOptions,
  ServerOptions,
} from 'vscode-languageclient/node';

import {
  DOCUMENT_SELECTOR,
  RawSettings,
  SECTION,
  ServerSettings,
  configurationItem,
  serverCommand,
  serverSettings,
} from './config';

let client: LanguageClient | undefined;
let output: vscode.OutputChannel;
/** Serialises start, stop and restart, which the user and setting changes can overlap. */
let lifecycle: Promise<void> = Promise.resolve();

/** The file-system path of the workspace folder of `uri`, else of the first folder. */
function folderPath(uri?: vscode.Uri): string | undefined {
  const folder =
    (uri && vscode.workspace.getWorkspaceFolder(uri)) ?? vscode.workspace.workspaceFolders?.[0];
  return folder && folder.uri.scheme === 'file' ? folder.uri.fsPath : undefined;
}

function rawSettings(uri?: vscode.Uri): RawSettings {
  const config = vscode.workspace.getConfiguration(SECTION, uri);
  return {
    path: config.get('path'),
    target: config.get('target'),
    templateDirs: config.get('templateDirs'),
    scriptDirs: config.get('scriptDirs'),
    warnings: config.get('warnings'),
  };
}

function settingsFor(uri?: vscode.Uri): ServerSettings {
  return serverSettings(rawSettings(uri), folderPath(uri));
}

function createClient(): LanguageClient {
  const command = serverCommand(rawSettings(), folderPath());
  const executable = { command: command.command, args: command.args, options: { cwd: command.cwd } };
  const serverOptions: ServerOptions = { run: executable, debug: executable };
  let self: LanguageClient | undefined;
  const clientOptions: LanguageClientOptions = {
    documentSelector: DOCUMENT_SELECTOR,
    outputChannel: output,
    initializationOptions: () => settingsFor(),
    // The client sends didChangeConfiguration for the section when it changes; the middleware
    // below replaces the raw settings with the ones the server reads (directories resolved).
    synchronize: { configurationSection: SECTION },
    middleware: {
      workspace: {
        configuration: async (params, token, next) => {
          const answers = await next(params, token);
          if (!Array.isArray(answers)) return answers;
          return params.items.map((item, i) => {
            const scope = item.scopeUri ? vscode.Uri.parse(item.scopeUri) : undefined;
            const ours = configurationItem(item.section, settingsFor(scope));
            return ours === undefined ? answers[i] : ours;
          });
        },
        didChangeConfiguration: async () => {
          if (!self || !self.isRunning()) return;
          await self.sendNotification(DidChangeConfigurationNotification.type, {
            settings: { [SECTION]: settingsFor() },
          });
        },
      },
    },
  };
  self = new LanguageClient('smachac', 'smachac', serverOptions, clientOptions);
  return self;
}

async function startClient(): Promise<void> {
  const started = createClient();
  client = started;
  try {
    await started.start();
  } catch (error) {
    const command = serverCommand(rawSettings(), folderPath()).command;
    const reason = error instanceof Error ? error.message : String(error);
    output.appendLine(`could not start \`${command} lsp\`: ${reason}`);
    const choice = await vscode.window.showErrorMessage(
      `smachac: could not start the language server \`${command} lsp\` (${reason}). ` +
        'Set "smachac.path" to the smachac executable.',
      'Open Settings',
    );
    if (choice === 'Open Settings') {
      await vscode.commands.executeCommand('workbench.action.openSettings', 'smachac.path');
    }
  }
}

async function stopClient(): Promise<void> {
  const stopping = client;
  client = undefined;
  if (!stopping) return;
  try {
    await stopping.dispose(); // stops the server first when it runs
  } catch (error) {
    output.appendLine(`stopping the server: ${error instanceof Error ? error.message : error}`);
  }
}

function queue(step: () => Promise<void>): Promise<void> {
  lifecycle = lifecycle.then(step, step);
  return lifecycle;
}

export function activate(context: vscode.ExtensionContext): Promise<void> {
  output = vscode.window.createOutputChannel('smachac');
  context.subscriptions.push(
    output,
    vscode.commands.registerCommand('smachac.restartServer', () =>
      queue(async () => {
        await stopClient();
        await startClient();
      }),
    ),
    vscode.workspace.onDidChangeConfiguration((event) => {
      if (event.affectsConfiguration(`${SECTION}.path`)) {
        void queue(async () => {
          await stopClient();
          await startClient();
        });
      }
    }),
  );
  return queue(startClient);
}

export function deactivate(): Promise<void> {
  return queue(stopClient);
}
