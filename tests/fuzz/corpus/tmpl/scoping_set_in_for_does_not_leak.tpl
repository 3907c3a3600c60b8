{% for i in [1, 2] %}[{{ x }}]{% set x = i %}({{ x }}){% endfor %}{{ x }}
{% for i in [1, 2] %}[{{ y }}]{% set y = i %}{% endfor %}[{{ y }}]
%%context
x: outer
