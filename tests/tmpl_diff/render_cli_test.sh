#!/usr/bin/env bash
# End-to-end test of `smachac render`: template by path and by name, JSON and YAML contexts,
# --block, -o, and the error format and exit codes.
#   usage: render_cli_test.sh <smachac>
set -u
smachac=${1:?usage: render_cli_test.sh <smachac>}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

check() {  # check <description> <expected> <actual>
  if [ "$2" != "$3" ]; then
    echo "FAIL $1"
    echo "  expected: $(printf '%q' "$2")"
    echo "  actual:   $(printf '%q' "$3")"
    failures=$((failures + 1))
  fi
}

mkdir -p "$work/tpl"
cat > "$work/tpl/Greet.tpl.py" <<'TPL'
{% block meta %}
name: Greet
{% endblock meta %}
{% block body %}
Hello {{ name }}! {{ items | join(', ') }}
{% endblock body %}
TPL
printf 'name: World\nitems: [a, yes, 1.50, "q"]\n' > "$work/ctx.yml"
printf '{"name": "JSON", "items": [1, 2.0]}' > "$work/ctx.json"
printf '{{ x | uper }}' > "$work/Bad.tpl"

out=$("$smachac" render "$work/tpl/Greet.tpl.py" --context "$work/ctx.yml" 2>&1)
check "render by path" $'\nname: Greet\n\n\nHello World! a, yes, 1.5, q' "$out"

out=$("$smachac" render Greet -I "$work/tpl" --context "$work/ctx.json" --block body 2>&1)
check "render a block by name" "Hello JSON! 1, 2.0" "$out"

out=$("$smachac" render Greet -I "$work/tpl" -context="$work/ctx.json" --skip-block=meta 2>&1)
check "single-dash options, skipped meta" $'\n\nHello JSON! 1, 2.0' "$out"

"$smachac" render Greet -I "$work/tpl" --context "$work/ctx.yml" --block body -o "$work/out.txt"
check "-o writes the file" "Hello World! a, yes, 1.5, q" "$(cat "$work/out.txt")"

out=$("$smachac" render "$work/Bad.tpl" 2>&1); code=$?
check "template error exit code" 1 "$code"
check "template error message" "$work/Bad.tpl:1:8: error: unknown filter \`uper\`; did you mean \`upper\`? [template-error]" "$out"

out=$("$smachac" render Nope -I "$work/tpl" 2>&1); code=$?
check "missing template exit code" 1 "$code"
check "missing template message" "Nope: error: template \`Nope\` not found; looked in \`$work/tpl\`, built-in \`smach/\` [template-error]" "$out"

printf '{"a": [1,' > "$work/bad.json"
out=$("$smachac" render Greet -I "$work/tpl" --context "$work/bad.json" 2>&1); code=$?
check "bad context exit code" 1 "$code"
case "$out" in
  "$work/bad.json:1:10: error: invalid JSON: "*"[context-error]") ;;
  *) check "bad context message" "$work/bad.json:1:10: error: invalid JSON: ... [context-error]" "$out" ;;
esac

"$smachac" render Greet -I "$work/tpl" --context "$work/missing.yml" > /dev/null 2>&1; code=$?
check "unreadable context exit code" 2 "$code"

"$smachac" render > /dev/null 2>&1; code=$?
check "usage error exit code" 2 "$code"

[ "$failures" -eq 0 ] && echo "render_cli_test: all checks passed"
exit $((failures > 0))
