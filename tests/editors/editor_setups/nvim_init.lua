-- The Neovim set-up of docs/editors.md (built-in LSP client, no plugins),
-- with strun taken from $STRUN.
vim.g.do_filetype_lua = 1  -- Neovim 0.7 (later versions always use it)
vim.filetype.add({ extension = { st = "iecst", TcPOU = "iecst", TcDUT = "iecst", TcGVL = "iecst" } })
vim.api.nvim_create_autocmd("FileType", {
  pattern = "iecst",
  callback = function(args)
    local id = vim.lsp.start_client({ name = "strun", cmd = { os.getenv("STRUN"), "lsp" }, root_dir = vim.fn.getcwd(),
                                      init_options = { target = "generic", strict = false } })
    vim.lsp.buf_attach_client(args.buf, id)
  end,
})
