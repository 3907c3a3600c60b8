{% from 'macros.tpl' import m %}{% call m(x) %}c{% endcall %}{{ exported }}{% block a %}{% endblock %}
%%context
x: [1, {k: v}]
