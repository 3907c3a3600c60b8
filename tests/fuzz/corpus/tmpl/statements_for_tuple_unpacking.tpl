{% for k, v in d.items() %}{{ k }}={{ v }};{% endfor %}
{% for k, v in d.items() | sort %}{{ k }}={{ v }};{% endfor %}
{% for n, name in pairs %}{{ n }}:{{ name }} {% endfor %}
{% for (a, (b, c)) in [(1, (2, 3))] %}{{ a }}{{ b }}{{ c }}{% endfor %}
%%context
d: {z: 1, a: 2, m: 3}
pairs: [[1, one], [2, two]]
