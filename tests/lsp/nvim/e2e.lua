-- Neovim's own LSP client against `smachac lsp`, set up as the README says (editors/nvim):
-- open a script, receive its diagnostics, jump to a definition, apply a code action.
-- Run by nvim_e2e.py: `nvim --headless --clean -u NONE -c 'luafile e2e.lua'` with
-- SMACHAC (the binary), SMACHAC_EDITORS (editors/) and SCRIPT (a copy of pick.yml) in the
-- environment. Ends Neovim with exit code 0 when every step passed, 1 otherwise.
local function fail(message)
  io.stderr:write('FAIL: ' .. message .. '\n')
  vim.cmd('cquit 1')
end

local function step(name)
  io.stdout:write('step: ' .. name .. '\n')
end

local function wait_for(what, condition)
  if not vim.wait(20000, condition, 20) then fail('timed out waiting for ' .. what) end
end

local function expect(what, actual, expected)
  if actual ~= expected then
    fail(string.format('%s: expected %s, got %s', what, vim.inspect(expected), vim.inspect(actual)))
  end
end

package.path = os.getenv('SMACHAC_EDITORS') .. '/nvim/?.lua;' .. package.path
require('smachac').setup({ cmd = { os.getenv('SMACHAC'), 'lsp' }, settings = { target = 'smach' } })
vim.cmd('edit ' .. vim.fn.fnameescape(os.getenv('SCRIPT')))
local buffer = vim.api.nvim_get_current_buf()

step('diagnostics')
wait_for('diagnostics', function() return #vim.diagnostic.get(buffer) > 0 end)
local diagnostic = vim.diagnostic.get(buffer)[1]
expect('message', diagnostic.message,
       'transition target `dnoe` is not a state in `pick`; did you mean `done`?')
expect('line', diagnostic.lnum, 13)
expect('column', diagnostic.col, 31)
expect('code', diagnostic.code, 'unknown-transition-target')

step('definition')
vim.api.nvim_win_set_cursor(0, { 10, 32 })  -- on `CLOSE` in OPEN's transitions
vim.lsp.buf.definition()
wait_for('the jump', function() return vim.api.nvim_win_get_cursor(0)[1] ~= 10 end)
expect('definition', vim.api.nvim_win_get_cursor(0)[1], 11)

step('code action')
vim.ui.select = function(items, options, on_choice)
  for _, item in ipairs(items) do
    if options.format_item(item):find('done', 1, true) then return on_choice(item) end
  end
  fail('no code action offers `done`: ' .. vim.inspect(vim.tbl_map(options.format_item, items)))
end
vim.api.nvim_win_set_cursor(0, { 14, 33 })
vim.lsp.buf.code_action()
wait_for('the edit', function() return vim.api.nvim_buf_get_lines(buffer, 13, 14, true)[1]:find('done') end)
expect('edited line', vim.api.nvim_buf_get_lines(buffer, 13, 14, true)[1],
       '      transitions: {succeeded: done}')
wait_for('the diagnostics to clear', function() return #vim.diagnostic.get(buffer) == 0 end)

step('done')
vim.cmd('qall!')
