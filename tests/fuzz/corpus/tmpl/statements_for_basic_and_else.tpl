{% for x in xs %}{{ x }}{% else %}none{% endfor %}
{% for x in empty %}{{ x }}{% else %}none{% endfor %}
{% for x in undefined_list %}{{ x }}{% else %}undefined iterates nothing{% endfor %}
{% for c in 'héllo' %}{{ c }}.{% endfor %}
{% for k in {'b': 1, 'a': 2} %}{{ k }}{% endfor %}
%%context
xs: [a, b]
empty: []
