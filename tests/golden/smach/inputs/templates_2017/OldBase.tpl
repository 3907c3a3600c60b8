{% extends "Base.tpl" %}
{% block imports %}
{{ super() }}
import math
{% endblock imports %}
