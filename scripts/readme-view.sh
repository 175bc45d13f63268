# Sourced (from the repository root) by the scripts that measure the README's picture: its view, run.sh's
# framing at 512x384 (readme_view), and a scratch folder removed on exit (out).
readme_view=(--scene builtin --width 512 --height 384 --camera -0.10,0.36,0.32,0.04,0,-0.05,42 --exposure 0.3)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
