{% for city, members in people | groupby('city', default='?') %}{{ city }}:{{ members | map(attribute='name') | join }};{% endfor %}
{% for city, members in people | selectattr('city', 'defined') | groupby('city', case_sensitive=true) %}{{ city }}={{ members | length }} {% endfor %}
%%context
people: [{name: a, city: NY}, {name: b, city: LA}, {name: c, city: ny}, {name: d}]
