{% set s = 'x' * 60000 %}{% for i in range(100000) %}{% set t = s ~ i %}{% endfor %}
