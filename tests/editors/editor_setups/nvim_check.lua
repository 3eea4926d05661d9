-- Diagnostics, hover and definition of main.st, written to $OUT.
local out = io.open(os.getenv("OUT"), "w")
local function say(s) out:write(s .. "\n") end
say("filetype " .. vim.bo.filetype)
vim.wait(15000, function() return #vim.diagnostic.get(0) > 0 end, 50)
for _, d in ipairs(vim.diagnostic.get(0)) do
  local code = d.code or (d.user_data and d.user_data.lsp and d.user_data.lsp.code)
  say(string.format("diagnostic %d:%d %s %s", d.lnum + 1, d.col + 1, tostring(code), d.message))
end
local params = vim.lsp.util.make_position_params()
params.position = { line = 6, character = 1 }
for _, r in pairs(vim.lsp.buf_request_sync(0, "textDocument/hover", params, 10000) or {}) do
  say("hover " .. (r.result and r.result.contents.value or "none"):gsub("\n", " "))
end
params.position = { line = 3, character = 12 }
for _, r in pairs(vim.lsp.buf_request_sync(0, "textDocument/definition", params, 10000) or {}) do
  local loc = r.result and (r.result.uri and r.result or r.result[1])
  say("definition " .. (loc and (loc.uri .. ":" .. loc.range.start.line) or "none"))
end
out:close()
vim.cmd("qa!")
