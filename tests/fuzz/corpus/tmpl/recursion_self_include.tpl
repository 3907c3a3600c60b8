{% include 'main.tpl' %}
