{% extends 'mid.tpl' %}{% block b %}child>{{ super() }}{% endblock %}
