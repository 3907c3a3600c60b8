{% extends 'State.tpl' %}
{% include 'Helper.tpl' %}
{% block imports %}
{{ super() }}
import child
{% endblock imports %}
%%context
defined_headers: []
