[{{ text | indent }}]
[{{ text | indent(2) }}]
[{{ text | indent(2, true) }}]
[{{ text | indent(2, first=true, blank=true) }}]
[{{ text | indent('> ') }}]
[{{ '' | indent(5, true) }}]
[{{ 'single' | indent(3) }}]
[{{ "trailing\n" | indent(2, true) }}]
[{{ "a\r\nb\x0bc\u2028d" | indent(1) }}]
%%context
text: "line1\nline2\n\nline4"
