{% block meta %}
name: Thing
{% endblock meta %}
{% extends 'base.tpl' %}
{% block imports %}import thing{% endblock imports %}
{% block body %}
body of {{ name }}
{% endblock body %}
%%context
name: FOO
