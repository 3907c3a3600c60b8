// Plain Node tests (node:test) of src/config.ts, and of package.json against it: no VS Code.
import * as assert from 'node:assert/strict';
import * as fs from 'node:fs';
import * as path from 'node:path';
import { describe, it } from 'node:test';

import {
  DOCUMENT_SELECTOR,
  SECTION,
  SETTING_KEYS,
  TARGETS,
  configurationItem,
  expandPath,
  resolveDirs,
  serverCommand,
  serverSettings,
  warningOptions,
} from '../config';

const HOME = '/home/user';
const FOLDER = '/work/project';

describe('expandPath', () => {
  it('resolves a relative path against the workspace folder', () => {
    assert.equal(expandPath('templates', FOLDER, HOME), '/work/project/templates');
    assert.equal(expandPath('./a/../b', FOLDER, HOME), '/work/project/b');
    assert.equal(expandPath('../common/templates', FOLDER, HOME), '/work/common/templates');
  });
  it('keeps an absolute path, normalised', () => {
    assert.equal(expandPath('/opt/smachac/templates/', FOLDER, HOME), '/opt/smachac/templates/');
    assert.equal(expandPath('/opt//x/./y', FOLDER, HOME), '/opt/x/y');
  });
  it('expands ~ and the ${workspaceFolder} and ${userHome} variables', () => {
    assert.equal(expandPath('~', FOLDER, HOME), HOME);
    assert.equal(expandPath('~/tpl', FOLDER, HOME), '/home/user/tpl');
    assert.equal(expandPath('${workspaceFolder}/tpl', FOLDER, HOME), '/work/project/tpl');
    assert.equal(expandPath('${userHome}/tpl', FOLDER, HOME), '/home/user/tpl');
  });
  it('leaves a relative path as it is without a workspace folder', () => {
    assert.equal(expandPath('templates', undefined, HOME), 'templates');
    assert.equal(expandPath('~/tpl', undefined, HOME), '/home/user/tpl');
  });
  it('trims surrounding blanks', () => {
    assert.equal(expandPath('  tpl ', FOLDER, HOME), '/work/project/tpl');
  });
});

describe('resolveDirs', () => {
  it('resolves every entry and keeps the order', () => {
    assert.deepEqual(resolveDirs(['b', '/abs', 'a'], FOLDER, HOME), [
      '/work/project/b',
      '/abs',
      '/work/project/a',
    ]);
  });
  it('drops empty and non-string entries and repeats', () => {
    assert.deepEqual(resolveDirs(['a', '', '  ', 3, null, './a', 'b'], FOLDER, HOME), [
      '/work/project/a',
      '/work/project/b',
    ]);
  });
  it('gives an empty list for anything but a list', () => {
    assert.deepEqual(resolveDirs(undefined, FOLDER, HOME), []);
    assert.deepEqual(resolveDirs('templates', FOLDER, HOME), []);
  });
});

describe('warningOptions', () => {
  it('keeps the command line spelling', () => {
    assert.deepEqual(warningOptions(['-Werror', '-Wno-unused-userdata', '-Wno-error=python-syntax']), [
      '-Werror',
      '-Wno-unused-userdata',
      '-Wno-error=python-syntax',
    ]);
  });
  it('adds a missing -W or dash', () => {
    assert.deepEqual(warningOptions(['error', 'Wno-unused-userdata', ' no-shadow ']), [
      '-Werror',
      '-Wno-unused-userdata',
      '-Wno-shadow',
    ]);
  });
  it('drops empty and non-string entries', () => {
    assert.deepEqual(warningOptions(['', '-W', 7, '-Werror']), ['-Werror']);
    assert.deepEqual(warningOptions('-Werror'), []);
  });
});

describe('serverSettings (initializationOptions, workspace/configuration)', () => {
  it('has the shape the server reads, with defaults', () => {
    assert.deepEqual(serverSettings({}, FOLDER, HOME), {
      target: 'smach',
      templateDirs: [],
      scriptDirs: [],
      warnings: [],
    });
  });
  it('carries every setting, directories resolved', () => {
    const settings = serverSettings(
      {
        path: 'build/smachac',
        target: 'flexbe',
        templateDirs: ['templates', '/opt/tpl'],
        scriptDirs: ['${workspaceFolder}/sub'],
        warnings: ['-Werror', '-Wno-unused-userdata'],
      },
      FOLDER,
      HOME,
    );
    assert.deepEqual(settings, {
      target: 'flexbe',
      templateDirs: ['/work/project/templates', '/opt/tpl'],
      scriptDirs: ['/work/project/sub'],
      warnings: ['-Werror', '-Wno-unused-userdata'],
    });
    assert.deepEqual(JSON.parse(JSON.stringify(settings)), settings);
  });
  it('falls back to smach for an unknown target', () => {
    for (const target of TARGETS) assert.equal(serverSettings({ target }, FOLDER, HOME).target, target);
    assert.equal(serverSettings({ target: 'ir' }, FOLDER, HOME).target, 'smach');
    assert.equal(serverSettings({ target: 3 }, FOLDER, HOME).target, 'smach');
  });
});

describe('serverCommand', () => {
  it('runs `smachac lsp` from PATH by default, in the workspace folder', () => {
    assert.deepEqual(serverCommand({}, FOLDER, HOME), { command: 'smachac', args: ['lsp'], cwd: FOLDER });
    assert.deepEqual(serverCommand({ path: '  ' }, FOLDER, HOME).command, 'smachac');
    assert.deepEqual(serverCommand({}, undefined, HOME), { command: 'smachac', args: ['lsp'] });
  });
  it('leaves a bare name to the PATH lookup', () => {
    assert.equal(serverCommand({ path: 'smachac-dev' }, FOLDER, HOME).command, 'smachac-dev');
  });
  it('resolves a relative path against the workspace folder', () => {
    assert.equal(
      serverCommand({ path: 'build/tools/smachac/smachac' }, FOLDER, HOME).command,
      '/work/project/build/tools/smachac/smachac',
    );
    assert.equal(serverCommand({ path: './smachac' }, FOLDER, HOME).command, '/work/project/smachac');
  });
  it('expands ~ and ${workspaceFolder}, keeps an absolute path', () => {
    assert.equal(serverCommand({ path: '~/bin/smachac' }, FOLDER, HOME).command, '/home/user/bin/smachac');
    assert.equal(
      serverCommand({ path: '${workspaceFolder}/build/smachac' }, FOLDER, HOME).command,
      '/work/project/build/smachac',
    );
    assert.equal(serverCommand({ path: '/usr/local/bin/smachac' }, FOLDER, HOME).command, '/usr/local/bin/smachac');
  });
  it('puts no other setting on the command line', () => {
    const command = serverCommand(
      { target: 'cpp', templateDirs: ['t'], scriptDirs: ['s'], warnings: ['-Werror'] },
      FOLDER,
      HOME,
    );
    assert.deepEqual(command.args, ['lsp']);
  });
});

describe('configurationItem (workspace/configuration answers)', () => {
  const settings = serverSettings({ target: 'cpp', warnings: ['-Werror'] }, FOLDER, HOME);
  it('answers the smachac section with the server settings', () => {
    assert.equal(configurationItem('smachac', settings), settings);
  });
  it('answers smachac.<key> with one value, null for an unknown key', () => {
    assert.equal(configurationItem('smachac.target', settings), 'cpp');
    assert.deepEqual(configurationItem('smachac.warnings', settings), ['-Werror']);
    assert.equal(configurationItem('smachac.path', settings), null);
  });
  it('leaves other sections to the editor', () => {
    assert.equal(configurationItem('yaml', settings), undefined);
    assert.equal(configurationItem('smachacx', settings), undefined);
    assert.equal(configurationItem(undefined, settings), undefined);
  });
});

describe('package.json', () => {
  const manifest = JSON.parse(fs.readFileSync(path.join(__dirname, '..', '..', 'package.json'), 'utf8'));
  it('contributes exactly the settings the extension reads', () => {
    const keys = Object.keys(manifest.contributes.configuration.properties).sort();
    assert.deepEqual(keys, SETTING_KEYS.map((k) => `${SECTION}.${k}`).sort());
  });
  it('offers the targets config.ts knows, defaulting to smach', () => {
    const target = manifest.contributes.configuration.properties['smachac.target'];
    assert.deepEqual(target.enum, [...TARGETS]);
    assert.equal(target.default, 'smach');
    assert.equal(manifest.contributes.configuration.properties['smachac.path'].default, 'smachac');
  });
  it('starts on YAML documents and has the restart command', () => {
    assert.ok(manifest.activationEvents.includes('onLanguage:yaml'));
    assert.deepEqual(
      DOCUMENT_SELECTOR.map((s) => s.language),
      ['yaml', 'yaml'],
    );
    assert.deepEqual(DOCUMENT_SELECTOR.map((s) => s.scheme).sort(), ['file', 'untitled']);
    const commands = manifest.contributes.commands.map((c: { command: string }) => c.command);
    assert.deepEqual(commands, ['smachac.restartServer']);
  });
  it('points main at the compiled extension', () => {
    assert.equal(path.normalize(manifest.main), path.normalize('./out/extension.js'));
    assert.ok(fs.existsSync(path.join(__dirname, '..', 'extension.js')), 'out/extension.js is built');
  });
  it('keeps @types/vscode within the engine that vscode-languageclient 9 needs', () => {
    assert.equal(manifest.engines.vscode, '^1.82.0');
    assert.match(manifest.devDependencies['@types/vscode'], /^~1\.82\./);
    assert.match(manifest.dependencies['vscode-languageclient'], /^\^9\./);
  });
});
