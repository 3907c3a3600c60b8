{{ site.name | strict }}{{ x | strict }}{{ 'ab' is short }}{{ x is short }}
%%context
x: 3
