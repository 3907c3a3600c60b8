line
    {{ 'kept indent' }}
    {# comment lstripped #}
  x {% if true %}not at line start{% endif %}
