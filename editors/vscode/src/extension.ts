// The strun extension: a language client that starts `strun lsp` and a
// debugger contribution that starts `strun debug` (docs/editors.md).
import * as vscode from "vscode";
import { LanguageClient, LanguageClientOptions, ServerOptions } from "vscode-languageclient/node";

let client: LanguageClient | undefined;

function strunPath(): string {
  return vscode.workspace.getConfiguration("strun").get<string>("path", "strun");
}

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  const config = vscode.workspace.getConfiguration("strun");
  const serverOptions: ServerOptions = { command: strunPath(), args: ["lsp"] };
  const clientOptions: LanguageClientOptions = {
    documentSelector: [
      { scheme: "file", language: "iec-st" },
      { scheme: "file", language: "twincat-st" },
    ],
    initializationOptions: {
      target: config.get<string>("target", "generic"),
      strict: config.get<boolean>("strict", false),
    },
  };
  client = new LanguageClient("strun", "strun language server", serverOptions, clientOptions);
  await client.start();

  // The debug adapter is strun itself, speaking DAP on stdin/stdout.
  context.subscriptions.push(
    vscode.debug.registerDebugAdapterDescriptorFactory("strun", {
      createDebugAdapterDescriptor(): vscode.ProviderResult<vscode.DebugAdapterDescriptor> {
        return new vscode.DebugAdapterExecutable(strunPath(), ["debug"]);
      },
    }),
    vscode.debug.registerDebugConfigurationProvider("strun", {
      resolveDebugConfiguration(folder, config): vscode.ProviderResult<vscode.DebugConfiguration> {
        // F5 without a launch.json: the workspace on the virtual clock.
        if (!config.type && !config.request && !config.name) {
          return {
            type: "strun",
            request: "launch",
            name: "strun: run on the virtual clock",
            program: folder ? folder.uri.fsPath : "${file}",
            args: ["--virtual"],
          };
        }
        return config;
      },
    }),
  );
}

export async function deactivate(): Promise<void> {
  if (client) await client.stop();
}
