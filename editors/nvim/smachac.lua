-- smachac's language server in Neovim (0.7 or later, with its built-in LSP client).
--
--   require('smachac').setup({
--     cmd = { 'smachac', 'lsp' },          -- the server command (default)
--     settings = { target = 'smach',       -- what `smachac lsp` reads from the editor:
--                  templateDirs = {},      -- -I, -S and -W as on the command line
--                  scriptDirs = {},
--                  warnings = {} },
--   })
--
-- One client serves every YAML buffer (with the server's completion as 'omnifunc'); the
-- server ignores YAML files that are not SMACHA scripts. Put this file on 'runtimepath' (e.g. ~/.config/nvim/lua/smachac.lua).
local M = {}

local client_id = nil

local function start(config)
  if client_id and vim.lsp.get_client_by_id(client_id) then return client_id end
  client_id = vim.lsp.start_client({
    name = 'smachac',
    cmd = config.cmd or { 'smachac', 'lsp' },
    root_dir = config.root_dir or vim.loop.cwd(),
    init_options = config.settings or {},
    settings = { smachac = config.settings or {} },
    on_attach = config.on_attach,
  })
  return client_id
end

function M.setup(config)
  config = config or {}
  local group = vim.api.nvim_create_augroup('smachac_lsp', { clear = true })
  vim.api.nvim_create_autocmd('FileType', {
    group = group,
    pattern = 'yaml',
    callback = function(args)
      local id = start(config)
      if not id then return end
      vim.lsp.buf_attach_client(args.buf, id)
      vim.bo[args.buf].omnifunc = 'v:lua.vim.lsp.omnifunc'  -- completion with <C-x><C-o>
    end,
  })
end

return M
