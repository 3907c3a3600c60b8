{% for v in [s, i, f, b, n, l, d, missing] %}{{ v is defined }}{{ v is undefined }}{{ v is none }}{{ v is string }}{{ v is number }}{{ v is integer }}{{ v is float }}{{ v is boolean }}{{ v is mapping }}{{ v is sequence }}{{ v is iterable }}{{ v is callable }}|{% endfor %}
%%context
s: str
i: 3
f: 2.5
b: true
n: null
l: [1]
d: {k: v}
