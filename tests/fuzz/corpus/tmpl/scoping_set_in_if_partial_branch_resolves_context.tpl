{% if false %}{% set v = 'branch' %}{% endif %}{{ v }}
{% if true %}{% set w = 1 %}{% else %}{% set w = 2 %}{% endif %}{{ w }}
%%context
v: ctx
