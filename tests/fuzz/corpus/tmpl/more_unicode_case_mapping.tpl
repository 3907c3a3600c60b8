{{ 'straße' | upper }} {{ 'ΟΔΟΣ ΟΔΟΣ.' | lower }} {{ 'ǅungla' | lower }} {{ 'ﬁne' | upper }} {{ 'ΣA' | lower }} {{ 'İstanbul' | lower | length }}
{{ 'éCOLE' | capitalize }} {{ 'ǳ' | title }} {{ 'hello wORLD'.title() }} {{ 'ß'.title() }} {{ "they're bill's" | title }}
