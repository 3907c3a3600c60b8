{% if true %}{% set a = 'from if' %}{% endif %}{{ a }}
{% if false %}{% set b = 'never' %}{% endif %}[{{ b }}]
