{% block defs %}
{% if 'def_greet' not in defined_headers %}
def greet(greeting, who):
    return '{}, {}!'.format(greeting, who)
{% do defined_headers.append('def_greet') %}
{% endif %}
{% endblock defs %}
