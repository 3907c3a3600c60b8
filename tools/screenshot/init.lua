-- The Neovim set-up of the README's screenshot: editors/nvim/smachac.lua, diagnostics as
-- virtual text and signs.
local editors, smachac = os.getenv('SMACHAC_EDITORS'), os.getenv('SMACHAC')
package.path = editors .. '/nvim/?.lua;' .. package.path
vim.o.termguicolors = true
vim.o.number = true
vim.o.signcolumn = 'yes'
vim.o.swapfile = false
vim.cmd('syntax on')
vim.diagnostic.config({ virtual_text = true, signs = true, underline = true })
vim.cmd('highlight NormalFloat guibg=#2e3440 guifg=#e5e9f0')
vim.cmd('highlight FloatBorder guibg=#2e3440 guifg=#88c0d0')
vim.cmd('highlight SignColumn guibg=NONE')
vim.lsp.handlers['textDocument/hover'] = vim.lsp.with(vim.lsp.handlers.hover, { border = 'rounded' })
require('smachac').setup({ cmd = { smachac, 'lsp' } })
