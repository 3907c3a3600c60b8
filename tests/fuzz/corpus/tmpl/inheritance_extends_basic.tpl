{% extends 'base.tpl' %}
ignored text after extends
{% block title %}Child title{% endblock %}
{% block body %}Child body, then {{ super() }}{% endblock body %}
