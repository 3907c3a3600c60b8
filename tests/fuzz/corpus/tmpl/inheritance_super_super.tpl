{% extends 'mid.tpl' %}{% block b %}child>{{ super.super() }}{% endblock %}
