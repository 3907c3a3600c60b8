x{% include 'includer.tpl' %}
