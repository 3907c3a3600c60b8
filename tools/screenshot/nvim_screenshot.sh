#!/usr/bin/env bash
# Draws the README's screenshot: Neovim with smachac's diagnostics and a hover, in tmux,
# captured with its colours and rendered to PNG.
#   tools/screenshot/nvim_screenshot.sh SMACHAC OUT.png
# Needs nvim, tmux and python3-pil (tools/install-deps installs them).
set -euo pipefail
smachac=$(realpath "$1")
out=$(realpath -m "$2")
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
session="smachac-shot-$$"
trap 'tmux kill-session -t "$session" 2>/dev/null || true; rm -rf "$work"' EXIT
cp "$here/demo.yml" "$work/pick_and_place.yml"
cd "$work"
tmux new-session -d -s "$session" -x 110 -y 40 \
  "env SMACHAC='$smachac' SMACHAC_EDITORS='$here/../../editors' HOME='$work' \
   XDG_CONFIG_HOME='$work' XDG_DATA_HOME='$work' XDG_STATE_HOME='$work' XDG_CACHE_HOME='$work' \
   nvim -n -i NONE -u '$here/init.lua' pick_and_place.yml"
sleep 3
# The cursor on PLACE's `template:` value, then the hover.
tmux send-keys -t "$session" ':call cursor(13, 20)' Enter
tmux send-keys -t "$session" ':lua vim.lsp.buf.hover()' Enter
sleep 2
tmux capture-pane -t "$session" -e -p > "$work/capture.txt"
/usr/bin/python3 "$here/render_terminal.py" "$work/capture.txt" "$out" 110 40
echo "wrote $out"
