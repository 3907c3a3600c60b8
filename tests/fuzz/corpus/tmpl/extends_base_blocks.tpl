{% extends 'base.tpl' %}{% block meta %}m{% endblock %}{% block b %}{{ super() }}{{ x | default('d') }}{% endblock %}
%%context
x: 'y'
