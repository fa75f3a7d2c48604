#!/usr/bin/env bash
# Drives a real editor, headless Neovim (Debian's `neovim`, 0.7 or later), against
# `essl server`: opens a shader with a missing `;`, waits for the diagnostics the server
# publishes, asks for a hover and the code actions, applies the fix, and checks each answer.
#
#   scripts/editor-neovim.sh            # builds essl without the GPU stack, then runs
#   ESSL=path/to/essl scripts/editor-neovim.sh
#
# Exits 0 when every check passes, 1 when one fails, 2 when Neovim is missing.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v nvim >/dev/null; then
    echo "editor-neovim: nvim is not installed (apt-get install neovim)" >&2
    exit 2
fi
if [[ -z "${ESSL:-}" ]]; then
    cargo build -q -p essl-cli --no-default-features --features mimalloc
    ESSL="$PWD/target/debug/essl"
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/spot.frag" <<'GLSL'
#version 300 es
precision highp float;
uniform vec3 u_light
in vec3 v_normal;
out vec4 color;
void main() {
    vec3 n = normalize(v_normal);
    color = vec4(vec3(dot(n, u_light)), 1.0);
}
GLSL

cat > "$work/drive.lua" <<'LUA'
local out = assert(io.open(vim.env.OUT, "w"))
local function say(s) out:write(s .. "\n") end
local client = vim.lsp.start_client({
  cmd = { vim.env.ESSL, "server" },
  root_dir = vim.env.WORK,
  on_exit = function(code) say("server exited " .. code) end,
})
vim.cmd("edit " .. vim.env.WORK .. "/spot.frag")
local buf = vim.api.nvim_get_current_buf()
vim.lsp.buf_attach_client(buf, client)
vim.wait(20000, function() return #vim.diagnostic.get(buf) > 0 end, 50)
for _, d in ipairs(vim.diagnostic.get(buf)) do
  say(string.format("diagnostic %d:%d %s %s", d.lnum + 1, d.col + 1, d.code or "", d.message:gsub("\n.*", "")))
end
local function at(line, col)
  return { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = { line = line, character = col } }
end
local hover = vim.lsp.buf_request_sync(buf, "textDocument/hover", at(7, 30), 10000)
for _, r in pairs(hover or {}) do
  if r.result then say("hover " .. r.result.contents.value:gsub("\n", " ")) end
end
local params = {
  textDocument = { uri = vim.uri_from_bufnr(buf) },
  range = { start = { line = 2, character = 0 }, ["end"] = { line = 2, character = 30 } },
  context = { diagnostics = {} },
}
local actions = vim.lsp.buf_request_sync(buf, "textDocument/codeAction", params, 10000)
for _, r in pairs(actions or {}) do
  for _, a in ipairs(r.result or {}) do
    say("action " .. a.title)
    if a.isPreferred then vim.lsp.util.apply_workspace_edit(a.edit, "utf-16") end
  end
end
say("line 3 after the fix: " .. vim.api.nvim_buf_get_lines(buf, 2, 3, false)[1])
vim.lsp.stop_client(client)
out:close()
vim.cmd("qa!")
LUA

OUT="$work/out.txt" ESSL="$ESSL" WORK="$work" timeout 60 \
    nvim --headless -u NONE -i NONE -c "luafile $work/drive.lua" >/dev/null 2>&1 || true
cat "$work/out.txt"

fail=0
expect() {
    if ! grep -qF -- "$1" "$work/out.txt"; then
        echo "editor-neovim: expected \`$1\`" >&2
        fail=1
    fi
}
expect "diagnostic 3:21 missing-semicolon"
expect "hover \`\`\`glsl uniform highp vec3 u_light \`\`\`"
expect "action add \`;\` at the end of the line"
expect "line 3 after the fix: uniform vec3 u_light;"
if [[ $fail == 0 ]]; then
    echo "editor-neovim: all checks passed"
fi
exit $fail
