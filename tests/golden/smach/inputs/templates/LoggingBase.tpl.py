{% extends "Base.tpl.py" %}
{% block imports %}
{{ super() }}
import logging
{% endblock imports %}
{% block main_def %}
{{ super() }}
    logging.basicConfig(level=logging.INFO)
{% endblock main_def %}
{% block base_footer %}
{{ super() }}
    logging.info('finished with %s', outcome)
{% endblock base_footer %}
