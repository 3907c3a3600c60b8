{% extends 'child.tpl' %}{% block a %}{{ super() }}{% endblock %}
