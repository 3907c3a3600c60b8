{% block defs %}
{% if 'def_helper' not in defined_headers %}
def helper(x):
    return x
{% do defined_headers.append('def_helper') %}
{% endif %}
{% endblock defs %}
